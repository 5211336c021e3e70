/**
 * radbake-lightmap.js — a three.js GLTFLoader plugin for radbake's engine file (`NAME.gltf`):
 * PBR materials as the input had them, plus the baked light from `MOZ_lightmap`.
 *
 * ```js
 * import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
 * import { RadbakeLightmapPlugin } from './radbake-lightmap.js';
 *
 * const loader = new GLTFLoader();
 * loader.register((parser) => new RadbakeLightmapPlugin(parser));          // the file's own exposure
 * // loader.register((parser) => new RadbakeLightmapPlugin(parser, { exposure: 2e-3 }));
 * const gltf = await loader.loadAsync('out/cornell_box/cornell_box.gltf');
 * scene.add(gltf.scene);   // no lights needed: the light is in the lightmap
 * ```
 *
 * Keep three.js's defaults for the rest: `renderer.outputColorSpace = SRGBColorSpace` and
 * `renderer.toneMapping = NoToneMapping` show the same colours as the display file
 * (`NAME_display.glb`); a tone mapper changes both alike.
 *
 * What it does, per material with `MOZ_lightmap {index, texCoord, intensity}`:
 * - `material.lightMap` = the page texture, loaded through the parser (so KHR_texture_transform,
 *   the sampler and embedded images work as for any glTF texture), `colorSpace` SRGBColorSpace
 *   (the PNG page is sRGB-encoded), `flipY` false (glTF's convention), `channel` = `texCoord`
 *   (1: TEXCOORD_1, which three.js calls `uv1`).
 * - `material.lightMapIntensity` = `intensity` × exposure. The page decodes to lux:
 *   E = srgb_to_linear(png) × intensity. three.js's light-map path shows a Lambertian surface as
 *   E × albedo / π (its luminance in cd/m2, for lux in), so multiplying by the exposure (display
 *   units per cd/m2) gives the same display value as the display file: luminance × exposure.
 * - Lambertian light map (`options.lambert`, default true): radbake baked a Lambertian reflectance
 *   ρ = baseColor × (1 − metallic), so the light a surface sends back is ρ × E, and the display
 *   file shows ρ × E / π. three.js's MeshStandardMaterial hands light-map irradiance to its
 *   diffuse lobe after taking off the specular lobe's share (1 − F_ss·E_ss − F_ms·E_ms: 1–5% on
 *   the Cornell box at the test's view angles, more at grazing ones; tests/web/plugin.test.mjs), and without an environment
 *   map that specular share shows nowhere: the surfaces render a few percent darker than the bake
 *   says. The plugin adds the light map's irradiance to the diffuse lobe as ρ × E / π instead
 *   (onBeforeCompile on MeshStandardMaterial / MeshPhysicalMaterial; ambient occlusion maps
 *   still apply); `lambert: false` keeps three.js's own split. If a three.js release renames what
 *   the patch relies on, the plugin warns once and leaves the shader alone.
 *
 * Exposure, first found wins:
 * 1. `options.exposure` (display units per cd/m2);
 * 2. the file's `extras.radbake.display_exposure` (root `extras`, or `asset.extras` when the root
 *    extras is not an object), the exposure radbake chose for the display file;
 * 3. fallback for files without it (radbake before the display file): π / `intensity`, which
 *    shows a white Lambertian surface under the page's full-scale irradiance (the PNG's 255) as
 *    display white.
 * `options.intensityScale` (default 1) multiplies the result, as a user's brightness slider.
 *
 * Options: { exposure?: number, intensityScale = 1, bakedLights = 'remove' | 'keep', lambert = true }.
 *
 * Baked lights: punctual lights (KHR_lights_punctual) whose definition carries
 * `extras.radbake.baked === true` are already in the lightmap; drawn again they would light the
 * scene twice. By default (`options.bakedLights = 'remove'`) the plugin takes the light off its
 * node before the scene is built (the node stays, as an empty Object3D with its children).
 * `'keep'` leaves them; GLTFLoader then exposes the marker as `light.userData.radbake.baked`.
 * The removed lights' names are listed in `gltf.userData.radbakeBakedLights`.
 *
 * After loading, `gltf.userData.radbake` holds the file's `extras.radbake` and
 * `gltf.userData.radbakeExposure` the exposure used ({ value, source }).
 *
 * @module radbake-lightmap
 */

import { ShaderChunk, SRGBColorSpace } from 'three';

export const EXTENSION_NAME = 'MOZ_lightmap';

function radbakeExtras(json) {
  const root = json.extras;
  if (root && typeof root === 'object' && root.radbake) return root.radbake;
  const asset = json.asset && json.asset.extras;
  if (asset && typeof asset === 'object' && asset.radbake) return asset.radbake;
  return null;
}

// What the Lambertian light-map patch needs from three.js's shader chunks (checked, not assumed).
const LAMBERT_PATCHABLE = () =>
  ShaderChunk.lights_fragment_maps.includes('irradiance += lightMapIrradiance;') &&
  ShaderChunk.lights_physical_fragment.includes('material.diffuseContribution') &&
  ShaderChunk.lights_fragment_end !== undefined;
let warnedUnpatchable = false;

function lambertLightMap(material) {
  const previous = material.onBeforeCompile;
  const previousKey = material.customProgramCacheKey;
  material.onBeforeCompile = function (shader, renderer) {
    if (previous) previous.call(this, shader, renderer);
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <lights_fragment_maps>', `#include <lights_fragment_maps>
#ifdef USE_LIGHTMAP
	// radbake: the light map's light goes to the diffuse lobe as baked (Lambertian), below.
	irradiance -= lightMapIrradiance;
#endif`)
      .replace('#include <lights_fragment_end>', `#include <lights_fragment_end>
#ifdef USE_LIGHTMAP
	reflectedLight.indirectDiffuse += lightMapIrradiance * BRDF_Lambert( material.diffuseContribution );
#endif`);
  };
  material.customProgramCacheKey = function () {
    return `radbake-lambert-lightmap;${previousKey.call(this)}`;
  };
  material.needsUpdate = true;
}

function positive(x) {
  return typeof x === 'number' && Number.isFinite(x) && x > 0;
}

export class RadbakeLightmapPlugin {
  /**
   * @param {import('three/addons/loaders/GLTFLoader.js').GLTFParser} parser
   * @param {{exposure?: number, intensityScale?: number, bakedLights?: 'remove'|'keep'}} [options]
   */
  constructor(parser, options = {}) {
    this.name = EXTENSION_NAME;
    this.parser = parser;
    this.options = { intensityScale: 1, bakedLights: 'remove', lambert: true, ...options };
    this.lightmapMaterials = new Set(); // glTF material indices with MOZ_lightmap
    this.radbake = radbakeExtras(parser.json);
    this.removedLights = [];
  }

  /** The exposure for a page of the given intensity: { value, source }. */
  exposureFor(intensity) {
    if (positive(this.options.exposure)) return { value: this.options.exposure, source: 'options.exposure' };
    const fromFile = this.radbake && this.radbake.display_exposure;
    if (positive(fromFile)) return { value: fromFile, source: 'extras.radbake.display_exposure' };
    return { value: positive(intensity) ? Math.PI / intensity : 1, source: 'fallback: pi / intensity' };
  }

  beforeRoot() {
    if (this.options.bakedLights !== 'remove') return null;
    const json = this.parser.json;
    const lights = json.extensions && json.extensions.KHR_lights_punctual && json.extensions.KHR_lights_punctual.lights;
    if (!Array.isArray(lights)) return null;
    const baked = (index) => {
      const def = lights[index];
      return !!(def && def.extras && def.extras.radbake && def.extras.radbake.baked === true);
    };
    for (const node of json.nodes || []) {
      const ref = node.extensions && node.extensions.KHR_lights_punctual;
      if (!ref || !baked(ref.light)) continue;
      this.removedLights.push(lights[ref.light].name || `light_${ref.light}`);
      delete node.extensions.KHR_lights_punctual;
    }
    return null;
  }

  extendMaterialParams(materialIndex, materialParams) {
    const def = this.parser.json.materials[materialIndex];
    const ext = def.extensions && def.extensions[EXTENSION_NAME];
    if (!ext || ext.index === undefined) return Promise.resolve();
    this.lightmapMaterials.add(materialIndex);
    const intensity = ext.intensity !== undefined ? ext.intensity : 1;
    const exposure = this.exposureFor(intensity);
    this.exposureUsed = exposure;
    materialParams.lightMapIntensity = intensity * exposure.value * this.options.intensityScale;
    const mapDef = { index: ext.index, texCoord: ext.texCoord !== undefined ? ext.texCoord : 0 };
    if (ext.extensions) mapDef.extensions = ext.extensions; // KHR_texture_transform on the page, if any
    return this.parser.assignTexture(materialParams, 'lightMap', mapDef, SRGBColorSpace).then((texture) => {
      if (!texture) return;
      texture.flipY = false;
      texture.channel = mapDef.texCoord;
    });
  }

  afterRoot(result) {
    if (this.options.lambert && this.lightmapMaterials.size > 0) {
      if (!LAMBERT_PATCHABLE()) {
        if (!warnedUnpatchable) console.warn('radbake-lightmap: this three.js shades light maps differently; lambert option ignored');
        warnedUnpatchable = true;
      } else {
        const done = new Set();
        for (const scene of result.scenes || [result.scene]) {
          scene.traverse((object) => {
            if (!object.isMesh) return;
            for (const material of [].concat(object.material)) {
              const assoc = this.parser.associations.get(material);
              if (done.has(material) || !material.isMeshStandardMaterial || !material.lightMap) continue;
              if (!assoc || !this.lightmapMaterials.has(assoc.materials)) continue;
              lambertLightMap(material);
              done.add(material);
            }
          });
        }
      }
    }
    result.userData = result.userData || {};
    result.userData.radbake = this.radbake;
    result.userData.radbakeExposure = this.exposureUsed || this.exposureFor(undefined);
    result.userData.radbakeBakedLights = this.removedLights;
    return null;
  }
}

export default RadbakeLightmapPlugin;

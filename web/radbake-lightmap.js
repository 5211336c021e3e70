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
 * Options: { exposure?: number, intensityScale = 1, bakedLights = 'remove' | 'keep', lambert = true,
 * directional = true }.
 *
 * Directional lightmaps: when the file was baked with `--directional sh`
 * (`extras.radbake.directional.mode === 'sh'`), each light-mapped material also reads its page's
 * four L1 pages (`NAME_sh_c0/c1x/c1y/c1z_N.png`, linear: value = png_offset + png_scale × png / 255)
 * and takes the irradiance for the shaded normal, normal map included:
 * E(n) = max(0, c0 + c1 · n_world) lux, times the light map's exposure. So a normal-mapped surface
 * shows its bumps under baked light. `directional: false` keeps the plain light map.
 * `gltf.userData.radbakeDirectionalMaterials` counts the materials that read them.
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

import { LinearFilter, NoColorSpace, ShaderChunk, SRGBColorSpace, TextureLoader } from 'three';

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

// Where the light-map chunk stands in a fragment shader: its include, or (after the directional
// patch has written it out) the marker that patch leaves after it.
const MAPS_INCLUDE = '#include <lights_fragment_maps>';
const MAPS_WRITTEN = '// radbake: lights_fragment_maps above';
const LIGHTMAP_LINE = 'vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;';

function lambertLightMap(material) {
  const previous = material.onBeforeCompile;
  const previousKey = material.customProgramCacheKey;
  material.onBeforeCompile = function (shader, renderer) {
    if (previous) previous.call(this, shader, renderer);
    const maps = shader.fragmentShader.includes(MAPS_INCLUDE) ? MAPS_INCLUDE : MAPS_WRITTEN;
    shader.fragmentShader = shader.fragmentShader
      .replace(maps, `${maps}
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

// Directional lightmaps (extras.radbake.directional, mode 'sh'): the light map's irradiance for the
// shaded normal (normal map included) from the L1 pages, E(n) = max(0, c0 + c1 . n_world) lux,
// times the exposure the light map has.
const SH_PATCHABLE = () => ShaderChunk.lights_fragment_maps.includes(LIGHTMAP_LINE);

function shLightMap(material, textures, scale, offset, exposure) {
  const previous = material.onBeforeCompile;
  const previousKey = material.customProgramCacheKey;
  material.onBeforeCompile = function (shader, renderer) {
    if (previous) previous.call(this, shader, renderer);
    shader.uniforms.radbakeSh0 = { value: textures[0] };
    shader.uniforms.radbakeSh1 = { value: textures[1] };
    shader.uniforms.radbakeSh2 = { value: textures[2] };
    shader.uniforms.radbakeSh3 = { value: textures[3] };
    shader.uniforms.radbakeShScale = { value: scale };
    shader.uniforms.radbakeShOffset = { value: offset };
    shader.uniforms.radbakeShExposure = { value: exposure };
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <lightmap_pars_fragment>', `#include <lightmap_pars_fragment>
uniform sampler2D radbakeSh0, radbakeSh1, radbakeSh2, radbakeSh3;
uniform vec4 radbakeShScale, radbakeShOffset;
uniform float radbakeShExposure;`)
      .replace(MAPS_INCLUDE, `${ShaderChunk.lights_fragment_maps.replace(LIGHTMAP_LINE, `// radbake: L1 irradiance for the shaded normal, in world space.
		vec3 radbakeN = inverseTransformDirection( normal, viewMatrix );
		vec3 radbakeC0 = radbakeShOffset.x + radbakeShScale.x * texture2D( radbakeSh0, vLightMapUv ).rgb;
		vec3 radbakeC1x = radbakeShOffset.y + radbakeShScale.y * texture2D( radbakeSh1, vLightMapUv ).rgb;
		vec3 radbakeC1y = radbakeShOffset.z + radbakeShScale.z * texture2D( radbakeSh2, vLightMapUv ).rgb;
		vec3 radbakeC1z = radbakeShOffset.w + radbakeShScale.w * texture2D( radbakeSh3, vLightMapUv ).rgb;
		vec3 lightMapIrradiance = max( radbakeC0 + radbakeC1x * radbakeN.x + radbakeC1y * radbakeN.y + radbakeC1z * radbakeN.z, vec3( 0.0 ) ) * radbakeShExposure;`)}
${MAPS_WRITTEN}`);
  };
  material.customProgramCacheKey = function () {
    return `radbake-sh-lightmap;${previousKey.call(this)}`;
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
    this.pageOfMaterial = new Map(); // glTF material index -> { page, intensity }
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
    const pages = (this.radbake && Array.isArray(this.radbake.pages)) ? this.radbake.pages : [];
    const page = pages.findIndex((p) => p && p.texture === ext.index);
    if (page >= 0) this.pageOfMaterial.set(materialIndex, { page, intensity });
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

  /** The L1 pages of `page` as linear textures read through TEXCOORD_1, with their scales and offsets. */
  loadShPage(page) {
    const d = this.radbake && this.radbake.directional;
    const sets = d && d.mode === 'sh' && Array.isArray(d.pages) ? d.pages : [];
    const names = ['sh_c0', 'sh_c1x', 'sh_c1y', 'sh_c1z'];
    const ordered = names.map((n) => sets.find((s) => s && s.coefficient === n));
    if (ordered.some((s) => !s || !Array.isArray(s.png) || typeof s.png[page] !== 'string')) return null;
    const base = this.parser.options.path || '';
    const loader = new TextureLoader(this.parser.options.manager);
    return Promise.all(ordered.map((s) => loader.loadAsync(base + s.png[page]).then((texture) => {
      texture.flipY = false;
      texture.colorSpace = NoColorSpace; // linear data: value = offset + scale * png
      texture.channel = 1;
      texture.minFilter = LinearFilter;
      texture.generateMipmaps = false;
      return texture;
    }))).then((textures) => ({
      textures,
      scale: ordered.map((s) => s.png_scale),
      offset: ordered.map((s) => s.png_offset),
    }));
  }

  /** Directional lightmaps ('sh'): each light-mapped material reads its page's L1 pages. */
  applyDirectional(result) {
    const d = this.radbake && this.radbake.directional;
    if (!d || d.mode !== 'sh' || this.options.directional === false) return Promise.resolve();
    if (!SH_PATCHABLE()) {
      console.warn('radbake-lightmap: this three.js reads light maps differently; directional pages ignored');
      return Promise.resolve();
    }
    const materials = this.lightMappedMaterials(result)
      .filter(([, index]) => this.pageOfMaterial.has(index))
      .map(([material, index]) => [material, this.pageOfMaterial.get(index)]);
    const loads = new Map();
    return Promise.all(materials.map(([material, { page, intensity }]) => {
      if (!loads.has(page)) loads.set(page, this.loadShPage(page));
      const load = loads.get(page);
      if (!load) return null;
      return load.then(({ textures, scale, offset }) => {
        shLightMap(material, textures, { x: scale[0], y: scale[1], z: scale[2], w: scale[3] },
          { x: offset[0], y: offset[1], z: offset[2], w: offset[3] }, material.lightMapIntensity / intensity);
        this.directionalMaterials = (this.directionalMaterials || 0) + 1;
      });
    }));
  }

  /** Each three.js material made from a glTF material with MOZ_lightmap, once: [material, glTF index]. */
  lightMappedMaterials(result) {
    const found = new Map();
    for (const scene of result.scenes || [result.scene]) {
      scene.traverse((object) => {
        if (!object.isMesh) return;
        for (const material of [].concat(object.material)) {
          const assoc = this.parser.associations.get(material);
          if (!material.lightMap || !assoc || !this.lightmapMaterials.has(assoc.materials)) continue;
          found.set(material, assoc.materials);
        }
      });
    }
    return [...found.entries()];
  }

  afterRoot(result) {
    return this.applyDirectional(result).then(() => this.finish(result));
  }

  finish(result) {
    if (this.options.lambert && this.lightmapMaterials.size > 0) {
      if (!LAMBERT_PATCHABLE()) {
        if (!warnedUnpatchable) console.warn('radbake-lightmap: this three.js shades light maps differently; lambert option ignored');
        warnedUnpatchable = true;
      } else {
        for (const [material] of this.lightMappedMaterials(result))
          if (material.isMeshStandardMaterial) lambertLightMap(material);
      }
    }
    result.userData = result.userData || {};
    result.userData.radbake = this.radbake;
    result.userData.radbakeExposure = this.exposureUsed || this.exposureFor(undefined);
    result.userData.radbakeBakedLights = this.removedLights;
    result.userData.radbakeDirectionalMaterials = this.directionalMaterials || 0;
    return null;
  }
}

export default RadbakeLightmapPlugin;

// Browser side of the render harness (render.mjs drives it through window.radbakeRender).
// One call: load a glTF with the stock GLTFLoader (optionally with the MOZ_lightmap plugin), render
// one frame with three.js's defaults (sRGB output, NoToneMapping, no lights added), read the frame
// back, and raycast the requested pixels so a test knows what surface and UV each one shows.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';
import { RadbakeLightmapPlugin } from '/web/radbake-lightmap.js';

function toBase64(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

const TEXTURE_SLOTS = ['map', 'lightMap', 'emissiveMap', 'aoMap', 'normalMap', 'roughnessMap', 'metalnessMap'];

window.radbakeRender = async (o) => {
  const t0 = performance.now();
  // A fresh canvas (and WebGL context) per render: nothing carries over from the previous one.
  document.body.replaceChildren();
  const canvas = document.createElement('canvas');
  document.body.appendChild(canvas);
  const renderer = new THREE.WebGLRenderer({ canvas, preserveDrawingBuffer: true, antialias: !!o.antialias });
  renderer.setPixelRatio(1);
  renderer.setSize(o.width, o.height, false);
  if (o.mode === 'stock' && (renderer.outputColorSpace !== THREE.SRGBColorSpace || renderer.toneMapping !== THREE.NoToneMapping))
    throw new Error('three.js defaults changed: output colour space or tone mapping is not sRGB / none');

  const loader = new GLTFLoader();
  if (o.meshopt) loader.setMeshoptDecoder(MeshoptDecoder);
  if (o.mode === 'plugin') loader.register((parser) => new RadbakeLightmapPlugin(parser, o.pluginOptions || {}));
  else if (o.mode !== 'stock') throw new Error(`unknown mode ${o.mode}`);
  const gltf = await loader.loadAsync(o.url);
  const tLoaded = performance.now();

  const scene = new THREE.Scene();
  scene.add(gltf.scene);
  const textures = new Set();
  const lights = [];
  const materials = new Map();
  scene.traverse((object) => {
    if (object.isLight) lights.push({ name: object.name, type: object.type, intensity: object.intensity, userData: object.userData });
    if (!object.isMesh) return;
    for (const material of [].concat(object.material)) {
      materials.set(material.uuid, {
        name: material.name,
        type: material.type,
        lightMap: !!material.lightMap,
        lightMapIntensity: material.lightMapIntensity,
        lightMapChannel: material.lightMap ? material.lightMap.channel : null,
        vertexColors: material.vertexColors,
      });
      for (const slot of TEXTURE_SLOTS) if (material[slot]) textures.add(material[slot]);
    }
  });
  if (o.mipmaps === 'force') {
    for (const texture of textures) {
      texture.generateMipmaps = true;
      texture.minFilter = THREE.LinearMipmapLinearFilter;
      texture.needsUpdate = true;
    }
  } else if (o.mipmaps && o.mipmaps !== 'as-written') throw new Error(`unknown mipmaps mode ${o.mipmaps}`);

  const camera = new THREE.PerspectiveCamera(o.camera.fov, o.width / o.height, o.camera.near ?? 0.01, o.camera.far ?? 1000);
  camera.position.fromArray(o.camera.position);
  camera.up.fromArray(o.camera.up ?? [0, 1, 0]);
  camera.lookAt(new THREE.Vector3().fromArray(o.camera.target));
  camera.updateMatrixWorld();
  scene.updateMatrixWorld(true);

  // A background no lit surface shows, so a test can tell the model's pixels from the rest.
  if (o.background) renderer.setClearColor(new THREE.Color().fromArray(o.background));
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const rgba = new Uint8Array(o.width * o.height * 4);
  gl.readPixels(0, 0, o.width, o.height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
  const flipped = new Uint8Array(rgba.length); // GL rows go bottom up; images top down
  const row = o.width * 4;
  for (let y = 0; y < o.height; y++) flipped.set(rgba.subarray((o.height - 1 - y) * row, (o.height - y) * row), y * row);
  const tRendered = performance.now();

  // What each requested pixel shows: the first mesh hit by the ray through the pixel's centre.
  const raycaster = new THREE.Raycaster();
  const hits = (o.points || []).map(([x, y]) => {
    raycaster.setFromCamera(new THREE.Vector2(((x + 0.5) / o.width) * 2 - 1, 1 - ((y + 0.5) / o.height) * 2), camera);
    const hit = raycaster.intersectObject(scene, true).find((h) => h.object.isMesh);
    if (!hit) return null;
    const material = Array.isArray(hit.object.material) ? hit.object.material[hit.face.materialIndex] : hit.object.material;
    const assoc = gltf.parser.associations;
    return {
      object: hit.object.name,
      node: assoc.get(hit.object) ? assoc.get(hit.object).nodes ?? null : null,
      material: material.name,
      materialIndex: assoc.get(material) ? assoc.get(material).materials ?? null : null,
      distance: hit.distance,
      point: hit.point.toArray(),
      normal: hit.face ? hit.face.normal.clone().transformDirection(hit.object.matrixWorld).toArray() : null,
      uv: hit.uv ? hit.uv.toArray() : null,
      uv1: hit.uv1 ? hit.uv1.toArray() : null,
    };
  });

  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  const result = {
    rgba: toBase64(flipped),
    hits,
    lights,
    materials: [...materials.values()],
    userData: gltf.userData || {},
    three: THREE.REVISION,
    gl: gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER),
    ms: { load: tLoaded - t0, render: tRendered - tLoaded },
  };
  renderer.dispose();
  renderer.forceContextLoss();
  return result;
};
window.radbakeReady = true;

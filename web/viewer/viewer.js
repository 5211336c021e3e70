// radbake view's page: the bake's engine file in three.js with its baked light (the MOZ_lightmap
// plugin), the glTF's cameras as bookmarks, and the illuminance where you click, read from the
// EXR page (the PNG holds 8 bits of it; the EXR the bake's own half floats).
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { EXRLoader } from 'three/addons/loaders/EXRLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { RadbakeLightmapPlugin } from '/radbake-lightmap.js';

const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(50, 1, 0.01, 1000);
const controls = new OrbitControls(camera, canvas);

function resize() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);

// Frames the whole scene from outside, looking at its middle.
function frame(root) {
  const box = new THREE.Box3().setFromObject(root);
  const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3()).length();
  camera.near = size / 1000;
  camera.far = size * 10;
  camera.position.copy(centre).add(new THREE.Vector3(0, size * 0.2, size * 0.9));
  controls.target.copy(centre);
  camera.updateProjectionMatrix();
  controls.update();
}

// A glTF camera as the view: its world position and direction; orbiting continues around a point
// straight ahead of it.
function useCamera(gltfCamera) {
  gltfCamera.updateWorldMatrix(true, false);
  camera.position.setFromMatrixPosition(gltfCamera.matrixWorld);
  camera.quaternion.setFromRotationMatrix(gltfCamera.matrixWorld);
  if (gltfCamera.isPerspectiveCamera) camera.fov = gltfCamera.fov;
  camera.updateProjectionMatrix();
  const ahead = new THREE.Vector3(0, 0, -1).applyQuaternion(camera.quaternion);
  controls.target.copy(camera.position).add(ahead);
  controls.update();
}

// EXR pages, loaded when first read: rows top first, RGBA floats.
const pages = new Map();
async function exrPage(url) {
  if (!pages.has(url)) {
    pages.set(url, new EXRLoader().setDataType(THREE.FloatType).loadAsync(url).then((texture) => {
      const { width, height, data } = texture.image;
      const channels = data.length / (width * height);
      // EXRLoader puts the file's last row first (a texture's origin is bottom-left).
      return { width, height, at: (x, y) => {
        const i = ((height - 1 - y) * width + x) * channels;
        return [data[i], data[i + 1], data[i + 2]];
      } };
    }));
  }
  return pages.get(url);
}

const state = { bakes: [], gltf: null, json: null, ready: null };

// The page a material's light map is on: MOZ_lightmap's texture, as extras.radbake.pages lists it.
function pageOf(material) {
  const association = state.gltf.parser.associations.get(material);
  if (!association || association.materials === undefined) return -1;
  const lightmap = state.json.materials[association.materials].extensions?.MOZ_lightmap;
  if (!lightmap) return -1;
  return state.json.extras.radbake.pages.findIndex((p) => p.texture === lightmap.index);
}

const raycaster = new THREE.Raycaster();

// What the bake holds at a pixel of the view (x right, y down): the surface, the page, the texel
// and the value in the bake's unit (lux for irradiance), the mean of R, G, B. Null where no baked
// surface is.
async function pick(x, y) {
  const ndc = new THREE.Vector2((x / canvas.clientWidth) * 2 - 1, -(y / canvas.clientHeight) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  const hit = raycaster.intersectObject(scene, true).find((h) => h.uv1);
  if (!hit) return null;
  const page = pageOf(hit.object.material);
  if (page < 0) return null;
  const record = state.json.extras.radbake;
  const exr = await exrPage(state.bakes[0].url + record.pages[page].exr);
  const tx = Math.min(exr.width - 1, Math.max(0, Math.floor(hit.uv1.x * exr.width)));
  const ty = Math.min(exr.height - 1, Math.max(0, Math.floor(hit.uv1.y * exr.height)));
  const rgb = exr.at(tx, ty);
  return { surface: hit.object.name, page, texel: [tx, ty], value: (rgb[0] + rgb[1] + rgb[2]) / 3, unit: record.unit };
}

canvas.addEventListener('click', async (event) => {
  const r = await pick(event.offsetX, event.offsetY);
  document.getElementById('readout').textContent = r
    ? `${r.surface}\n${r.value.toPrecision(4)} ${r.unit}\npage ${r.page}, texel ${r.texel[0]}, ${r.texel[1]}`
    : 'no baked surface there';
});

function loop() {
  controls.update();
  renderer.render(scene, camera);
  requestAnimationFrame(loop);
}

async function start() {
  state.bakes = await (await fetch('/api/bakes')).json();
  const a = state.bakes[0];
  document.getElementById('title').textContent = `radbake view: ${a.folder}`;
  const loader = new GLTFLoader();
  loader.register((parser) => new RadbakeLightmapPlugin(parser));
  state.gltf = await loader.loadAsync(a.url + a.gltf);
  state.json = state.gltf.parser.json;
  scene.add(state.gltf.scene);
  resize();
  frame(state.gltf.scene);
  const select = document.getElementById('camera');
  state.gltf.cameras.forEach((c, k) => select.add(new Option(c.name || `camera ${k}`, String(k))));
  select.addEventListener('change', () => {
    const k = Number(select.value);
    if (k < 0) frame(state.gltf.scene);
    else useCamera(state.gltf.cameras[k]);
  });
  loop();
}

// For tests and scripts: wait for `ready`, choose a camera, read a pixel.
state.ready = start();
window.radbakeView = {
  ready: state.ready,
  useCamera: (k) => { useCamera(state.gltf.cameras[k]); renderer.render(scene, camera); },
  pick,
};

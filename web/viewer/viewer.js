// radbake view's page: one bake (or two to compare) in three.js. Display modes: the baked light as
// an engine shows it (the MOZ_lightmap plugin), the lightmap alone, the vertex light, false colour
// of the illuminance (and of the daylight factor when the bake has one), and the difference of two
// bakes as `radbake diff` draws it. The value where you click is read from the EXR page (the PNG
// holds 8 bits of it; the EXR the bake's own half floats).
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { EXRLoader } from 'three/addons/loaders/EXRLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { RadbakeLightmapPlugin } from '/radbake-lightmap.js';
import { drawLegend, niceNumberAtOrAbove, turbo, turboGlsl } from '/viewer/legend.js';

const started = performance.now();
// The bakes start loading before the renderer is made: a WebGL context takes a third of a second
// in a software renderer (headless Chromium's), and the network need not wait for it.
const loading = loadBakes();

const $ = (id) => document.getElementById(id);
const canvas = $('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.toneMapping = THREE.LinearToneMapping;  // exposure in EV: a plain multiplier, 1 at 0 EV
const camera = new THREE.PerspectiveCamera(50, 1, 0.01, 1000);
const controls = new OrbitControls(camera, canvas);

// One loaded bake: its glTF, its JSON, and per display mode the material each of its meshes wears;
// its EXR pages as float textures come later (pagesLoading): the baked light's first frame needs
// only the glTF and its PNG pages, the readout and the analysis modes the EXRs.
async function loadBake(bake, exposure) {
  const loader = new GLTFLoader();
  loader.register((parser) => new RadbakeLightmapPlugin(parser, exposure ? { exposure } : {}));
  const gltf = await loader.loadAsync(bake.url + bake.gltf);
  const json = gltf.parser.json;
  const record = json.extras.radbake;
  const pagesLoading = Promise.all(record.pages.map((p) => new EXRLoader().setDataType(THREE.FloatType).loadAsync(bake.url + p.exr)))
    .then((pages) => {
      for (const page of pages) {
        page.minFilter = page.magFilter = THREE.NearestFilter;
        page.generateMipmaps = false;
      }
      return pages;
    });
  const scene = new THREE.Scene();
  scene.add(gltf.scene);
  const meshes = [];
  gltf.scene.traverse((o) => {
    if (o.isMesh) meshes.push({ mesh: o, baked: o.material, page: pageOf(gltf, json, o.material) });
  });
  return { bake, gltf, json, record, pages: [], pagesLoading, scene, meshes, sensors: await loadSensors(bake, scene), probes: probeSpheres(record, scene) };
}

// The bake's light probes (extras.radbake.probes, --probes) as white spheres lit by each probe:
// a Lambertian sphere of reflectance 1 shows E(n) / pi cd/m2 (E from the probe's L2 coefficients,
// Ramamoorthi and Hanrahan), at the display exposure; null when the bake has none.
function probeSpheres(record, scene) {
  const probes = record.probes && Array.isArray(record.probes.probes) ? record.probes.probes : [];
  if (!probes.length) return null;
  const geometry = new THREE.SphereGeometry(Math.max(1e-3, 0.15 * (record.probes.spacing_m || 0.1)), 24, 16);
  const group = new THREE.Group();
  group.name = 'radbake light probes';
  for (const probe of probes) {
    const material = new THREE.ShaderMaterial({
      uniforms: { sh: { value: probe.sh.map((c) => new THREE.Vector3(c[0], c[1], c[2])) },
        exposure: { value: record.display_exposure || 1 } },
      vertexShader: `varying vec3 vNormal;
void main() { vNormal = normalize(mat3(modelMatrix) * normal); gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0); }`,
      fragmentShader: `uniform vec3 sh[9]; uniform float exposure; varying vec3 vNormal;
void main() {
  vec3 n = normalize(vNormal);
  float pi = 3.14159265;
  vec3 e = pi * 0.282095 * sh[0]
    + (2.0 * pi / 3.0) * 0.488603 * (sh[1] * n.y + sh[2] * n.z + sh[3] * n.x)
    + (pi / 4.0) * (1.092548 * (sh[4] * n.x * n.y + sh[5] * n.y * n.z + sh[7] * n.x * n.z)
                    + 0.315392 * sh[6] * (3.0 * n.z * n.z - 1.0) + 0.546274 * sh[8] * (n.x * n.x - n.y * n.y));
  gl_FragColor = vec4(max(e, vec3(0.0)) / pi * exposure, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}`,
    });
    const sphere = new THREE.Mesh(geometry, material);
    sphere.position.fromArray(probe.position);
    group.add(sphere);
  }
  group.visible = false;
  scene.add(group);
  return group;
}

// The bake's sensors (sensors.csv: work plane and listed points), as points drawn over the scene
// in false colour, in front of whatever is nearer, glazing too (drawn last, with the transparent
// objects: a grid of readings, not a surface); null when
// it has none.
async function loadSensors(bake, scene) {
  if (!(bake.report.files || []).includes('sensors.csv')) return null;
  const rows = (await (await fetch(bake.url + 'sensors.csv')).text()).trim().split('\n').slice(1).map((l) => l.split(',').map(Number));
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(rows.flatMap((r) => r.slice(0, 3)), 3));
  geometry.setAttribute('color', new THREE.Float32BufferAttribute(new Float32Array(rows.length * 3), 3));
  const points = new THREE.Points(geometry, new THREE.PointsMaterial({
    size: 9, sizeAttenuation: false, vertexColors: true, toneMapped: false, depthTest: false, transparent: true }));
  points.renderOrder = 1;
  points.visible = false;
  scene.add(points);
  return { points, lux: rows.map((r) => r[6]) };
}

// The page a material's light map is on: MOZ_lightmap's texture, as extras.radbake.pages lists it.
function pageOf(gltf, json, material) {
  const association = gltf.parser.associations.get(material);
  const lightmap = association && json.materials[association.materials]?.extensions?.MOZ_lightmap;
  if (!lightmap) return -1;
  return json.extras.radbake.pages.findIndex((p) => p.texture === lightmap.index);
}

// What a light meter reads of linear RGB: the photopic (CIE 1931 Y) weights of sRGB's primaries,
// as radbake's readings are (base/math.h).
const PHOTOPIC = [0.2126, 0.7152, 0.0722];

// The EXR pages' photopic value at a texel, rows top first (EXRLoader puts the file's last row
// first: a texture's origin is bottom-left).
function texelValue(page, x, y) {
  const { width, height, data } = page.image;
  const channels = data.length / (width * height);
  const i = ((height - 1 - y) * width + x) * channels;
  return PHOTOPIC[0] * data[i] + PHOTOPIC[1] * data[i + 1] + PHOTOPIC[2] * data[i + 2];
}

// The automatic top of a false-colour scale: the 99th percentile of the covered texels, rounded up
// to 1, 2, 2.5 or 5 x 10^k, as radbake's own false-colour images choose it.
function automaticMax(bake, factor) {
  const values = litValues(bake);
  if (!values.length) return 1;
  return niceNumberAtOrAbove(factor * values[Math.min(values.length - 1, Math.ceil(0.99 * values.length) - 1)]);
}

// The photopic values of a bake's covered texels (every other one each way), sorted; worked out
// once (a typed array sorts numerically, and fast: a million texels in tens of milliseconds).
function litValues(bake) {
  if (bake.litValues) return bake.litValues;
  let count = 0;
  for (const page of bake.pages) count += Math.ceil(page.image.width / 2) * Math.ceil(page.image.height / 2);
  const values = new Float32Array(count);
  let n = 0;
  for (const page of bake.pages) {
    const { width, height } = page.image;
    for (let y = 0; y < height; y += 2) for (let x = 0; x < width; x += 2) {
      const v = texelValue(page, x, y);
      if (v > 0) values[n++] = v;
    }
  }
  bake.litValues = values.subarray(0, n).sort();
  return bake.litValues;
}

const MODES = { baked: -1, lightmap: 0, falsecolour: 1, difference: 2, vertex: 3 };

const vertexShader = `
  attribute vec2 uv1;
  varying vec2 vUv1;
  #ifdef VERTEX_LIGHT
  attribute vec3 _baked_light;
  varying vec3 vLight;
  #endif
  void main() {
    vUv1 = uv1;
    #ifdef VERTEX_LIGHT
    vLight = _baked_light;
    #endif
    gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
  }`;

const fragmentShader = `
  uniform sampler2D pageA, pageB;
  uniform int mode;
  uniform float displayScale;  // display value per lux on a white Lambertian surface
  uniform float valueScale;    // what the false colour shows per lux (1, or 100 / E_hz for a daylight factor)
  uniform float maxValue, decades, logarithmic;
  uniform float floorValue, differenceScale;
  varying vec2 vUv1;
  #ifdef VERTEX_LIGHT
  varying vec3 vLight;
  #endif
  ${turboGlsl}
  vec3 srgbToLinear(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c)); }
  void main() {
    vec2 t = vec2(vUv1.x, 1.0 - vUv1.y);
    float a = dot(texture2D(pageA, t).rgb, vec3(0.2126, 0.7152, 0.0722));  // photopic, as PHOTOPIC
    vec3 c;
    if (mode == 0) {
      c = texture2D(pageA, t).rgb * displayScale;  // in colour: the bleeding the bake is about
    } else if (mode == 1) {
      float v = a * valueScale;
      float f = logarithmic > 0.5 ? (log(max(v, 1e-30) / maxValue) / log(10.0) + decades) / decades : v / maxValue;
      c = srgbToLinear(turbo(clamp(f, 0.0, 1.0)));
    } else if (mode == 2) {
      // As radbake diff compares pages: the mean of R, G, B.
      float ma = dot(texture2D(pageA, t).rgb, vec3(1.0 / 3.0)), b = dot(texture2D(pageB, t).rgb, vec3(1.0 / 3.0));
      float s = clamp((b - ma) / max(ma, floorValue) / differenceScale, -1.0, 1.0);
      c = s > 0.0 ? mix(vec3(1.0), vec3(1.0, 0.0, 0.0), s) : mix(vec3(1.0), vec3(0.0, 0.0, 1.0), -s);
    } else {
      #ifdef VERTEX_LIGHT
      c = vLight * displayScale;
      #endif
    }
    gl_FragColor = vec4(c, 1.0);
    #include <colorspace_fragment>
  }`;

// The material a mesh wears in a mode that reads pages or vertex light.
function analysisMaterial(uniforms, pageA, pageB, vertexLight) {
  return new THREE.ShaderMaterial({
    vertexShader, fragmentShader, toneMapped: false, side: THREE.FrontSide,
    defines: vertexLight ? { VERTEX_LIGHT: 1 } : {},
    uniforms: { ...uniforms, pageA: { value: pageA }, pageB: { value: pageB ?? pageA } },
  });
}

const state = { bakes: [], a: null, b: null, mode: 'baked', split: 0.5, walk: false, uniforms: null, scale: null };

// Whether B's pages lie over A's texel for texel (the same scene baked with the same atlas
// options): the difference compares them so, as radbake diff does.
function sameLayout(a, b) {
  return b && b.pages.length === a.pages.length &&
    b.pages.every((p, k) => p.image.width === a.pages[k].image.width && p.image.height === a.pages[k].image.height);
}

function setupMaterials() {
  const { a, b } = state;
  const u = state.uniforms = {
    mode: { value: 0 }, displayScale: { value: 1 }, valueScale: { value: 1 }, maxValue: { value: 1 },
    decades: { value: 3 }, logarithmic: { value: 0 }, floorValue: { value: 0 }, differenceScale: { value: 0.1 },
  };
  for (const bake of [a, b]) {
    if (!bake) continue;
    for (const m of bake.meshes) {
      const page = bake.pages[m.page];
      const other = bake === a && sameLayout(a, b) ? b.pages[m.page] : null;
      m.analysis = m.page >= 0 ? analysisMaterial(u, page, other, false) : null;
      m.vertex = m.mesh.geometry.attributes._baked_light ? analysisMaterial(u, page, null, true) : null;
    }
  }
  // radbake diff's floor: 10% of the reference's mean texel value (for the difference, so only
  // with two bakes).
  if (!b) return;
  let sum = 0, n = 0;
  for (const page of a.pages) for (let i = 0; i < page.image.data.length; i += 4) {
    const v = (page.image.data[i] + page.image.data[i + 1] + page.image.data[i + 2]) / 3;
    if (v > 0) sum += v, n++;
  }
  u.floorValue.value = n ? 0.1 * sum / n : 0;
}

// What the false colour shows: lux, or the daylight factor where the bake has one.
function daylightReference() {
  const d = state.a.bake.report.daylight;
  return d && state.a.bake.report.options?.['daylight-factor'] === 'yes' ? d.sky_horizontal_illuminance_lx : 0;
}

function applyMode() {
  const mode = state.mode, u = state.uniforms;
  const daylight = mode === 'daylight';
  u.mode.value = mode === 'daylight' ? MODES.falsecolour : MODES[mode] ?? 0;
  const exposure = (state.a.record.display_exposure || 1) * Math.pow(2, Number($('ev').value));
  renderer.toneMappingExposure = Math.pow(2, Number($('ev').value));
  u.displayScale.value = exposure / Math.PI;
  u.valueScale.value = daylight ? 100 / daylightReference() : 1;
  u.logarithmic.value = $('scale').value === 'log' ? 1 : 0;
  const typed = Number($('max').value);
  const sensors = state.a.sensors;
  u.maxValue.value = typed > 0 ? typed
    : mode === 'sensors' ? niceNumberAtOrAbove(Math.max(...sensors.lux))
    // A daylight factor is at most 100% (a surface in the open); the texels' noise can put the
    // 99th percentile a little above it, which rounding would make 200.
    : daylight ? Math.min(100, automaticMax(state.a, u.valueScale.value))
    : automaticMax(state.a, u.valueScale.value);
  if (sensors) {
    sensors.points.visible = mode === 'sensors';
    const colours = sensors.points.geometry.attributes.color, colour = new THREE.Color();
    sensors.lux.forEach((lux, k) => {
      const f = u.logarithmic.value > 0.5 ? (Math.log10(lux / u.maxValue.value) + 3) / 3 : lux / u.maxValue.value;
      const [r, g, b] = turbo(f);
      colour.setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace);
      colours.setXYZ(k, colour.r, colour.g, colour.b);
    });
    colours.needsUpdate = true;
  }
  for (const bake of [state.a, state.b]) {
    if (!bake) continue;
    for (const m of bake.meshes) {
      m.mesh.material = mode === 'baked' || mode === 'sensors' ? m.baked : mode === 'vertex' ? m.vertex ?? m.baked : m.analysis ?? m.baked;
    }
  }
  const legend = $('legend');
  const unit = daylight ? '%' : state.a.record.unit;
  if (mode === 'falsecolour' || mode === 'daylight' || mode === 'sensors')
    drawLegend(legend, { kind: 'turbo', max: u.maxValue.value, logarithmic: u.logarithmic.value > 0.5, decades: 3, unit });
  else if (mode === 'difference') drawLegend(legend, { kind: 'difference', scale: u.differenceScale.value });
  legend.style.display = ['falsecolour', 'daylight', 'sensors', 'difference'].includes(mode) ? 'block' : 'none';
  state.scale = { max: u.maxValue.value, logarithmic: u.logarithmic.value > 0.5, decades: 3, unit };
}

// The exposure slider's range and start from the bake's own light: at its lowest EV the brightest
// lit texels (the 99.9th percentile) show at a quarter of white, at its highest the dim ones (the
// 2nd percentile) at white; it starts at the file's own exposure (display_exposure: the median lit
// surface of what the display camera sees at 0.18), or, for a file without one, there.
function exposureFromTheData() {
  const scale = (state.a.record.display_exposure || 1) / Math.PI;
  const values = litValues(state.a);
  if (!values.length) return;
  const at = (q) => scale * values[Math.min(values.length - 1, Math.floor(q * values.length))];
  const start = state.a.record.display_exposure ? 0 : Math.round(2 * Math.log2(0.18 / at(0.5))) / 2;
  const ev = $('ev');
  ev.min = String(Math.min(start - 3, Math.floor(Math.log2(0.25 / at(0.999)))));
  ev.max = String(Math.max(start + 3, Math.ceil(Math.log2(1 / at(0.02)))));
  ev.value = String(start);
}

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
  camera.fov = 50;
  camera.near = size / 1000;
  camera.far = size * 10;
  camera.position.copy(centre).add(new THREE.Vector3(0, size * 0.2, size * 0.9));
  controls.target.copy(centre);
  camera.updateProjectionMatrix();
  controls.update();
}

// The diagonal of bake A's scene, worked out once (walking asks it every frame).
function sceneSize() {
  state.a.size ??= new THREE.Box3().setFromObject(state.a.scene).getSize(new THREE.Vector3()).length();
  return state.a.size;
}

// The view a person wants first: the glTF's first camera; else the one radbake chose for the
// display file (report.json display.camera_view: inside the largest room, or outside looking at the
// model); else the whole scene framed.
function firstView() {
  const view = state.a.bake.report.display?.camera_view;
  if (state.a.gltf.cameras.length) useCamera(state.a.gltf.cameras[0]);
  else if (view) useView(view);
  else frame(state.a.scene);
}

function useView(view) {
  const size = sceneSize();
  const eye = new THREE.Vector3(...view.eye), forward = new THREE.Vector3(...view.forward).normalize();
  camera.position.copy(eye);
  camera.fov = (view.yfov * 180) / Math.PI;
  camera.near = view.znear;
  camera.far = size * 10;
  camera.lookAt(eye.clone().add(forward));
  camera.updateProjectionMatrix();
  controls.target.copy(eye).addScaledVector(forward, Math.min(1, 0.1 * size));
  controls.update();
}

// A glTF camera as the view; orbiting continues around a point straight ahead of it.
function useCamera(gltfCamera) {
  gltfCamera.updateWorldMatrix(true, false);
  camera.position.setFromMatrixPosition(gltfCamera.matrixWorld);
  camera.quaternion.setFromRotationMatrix(gltfCamera.matrixWorld);
  if (gltfCamera.isPerspectiveCamera) camera.fov = gltfCamera.fov;
  // Its near plane, and a far one that reaches the whole scene (a model in millimetres is
  // thousands of units across).
  const size = sceneSize();
  camera.near = gltfCamera.near > 0 ? gltfCamera.near : size / 1000;
  camera.far = Math.max(gltfCamera.far > 0 ? gltfCamera.far : 0, size * 10);
  camera.updateProjectionMatrix();
  controls.target.copy(camera.position).add(new THREE.Vector3(0, 0, -1).applyQuaternion(camera.quaternion));
  controls.update();
}

// First-person walk: W, A, S, D move along the ground plane, dragging turns the head.
const keys = new Set();
window.addEventListener('keydown', (e) => keys.add(e.key.toLowerCase()));
window.addEventListener('keyup', (e) => keys.delete(e.key.toLowerCase()));
canvas.addEventListener('pointermove', (e) => {
  if (!state.walk || !(e.buttons & 1)) return;
  const euler = new THREE.Euler().setFromQuaternion(camera.quaternion, 'YXZ');
  euler.y -= e.movementX * 0.004;
  euler.x = Math.max(-1.5, Math.min(1.5, euler.x - e.movementY * 0.004));
  camera.quaternion.setFromEuler(euler);
});
function walk(seconds) {
  const size = sceneSize();
  const ahead = new THREE.Vector3(0, 0, -1).applyQuaternion(camera.quaternion).setY(0).normalize();
  const right = new THREE.Vector3().crossVectors(ahead, new THREE.Vector3(0, 1, 0));
  const step = new THREE.Vector3();
  if (keys.has('w')) step.add(ahead);
  if (keys.has('s')) step.sub(ahead);
  if (keys.has('d')) step.add(right);
  if (keys.has('a')) step.sub(right);
  if (step.lengthSq() > 0) camera.position.addScaledVector(step.normalize(), size * 0.15 * seconds);
}

const raycaster = new THREE.Raycaster();

// What bake A holds at a point of the view (x right, y down, in CSS pixels: pixel (i, j) has its
// centre at i + 0.5, j + 0.5): the surface, the page, the texel and the value in the bake's unit
// (lux for irradiance), photopic. Null where no baked surface is.
function pick(x, y) {
  const ndc = new THREE.Vector2((x / canvas.clientWidth) * 2 - 1, -(y / canvas.clientHeight) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  const hit = raycaster.intersectObject(state.a.scene, true).find((h) => h.uv1);
  const entry = hit && state.a.meshes.find((m) => m.mesh === hit.object);
  if (!entry || entry.page < 0) return null;
  const page = state.a.pages[entry.page];
  const { width, height } = page.image;
  const tx = Math.min(width - 1, Math.max(0, Math.floor(hit.uv1.x * width)));
  const ty = Math.min(height - 1, Math.max(0, Math.floor(hit.uv1.y * height)));
  return { surface: hit.object.name, page: entry.page, texel: [tx, ty], value: texelValue(page, tx, ty), unit: state.a.record.unit };
}

canvas.addEventListener('click', (event) => {
  if (state.walk) return;
  const r = pick(event.offsetX, event.offsetY);
  $('readout').textContent = r
    ? `${r.surface}\n${r.value.toPrecision(4)} ${r.unit}\npage ${r.page}, texel ${r.texel[0]}, ${r.texel[1]}`
    : 'no baked surface there';
});

function render() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  // The difference is a comparison of its own, drawn on A.
  if (state.b && $('compare').value === 'split' && state.mode !== 'difference') {
    const cut = Math.round(w * state.split);
    renderer.setScissorTest(true);
    renderer.setScissor(0, 0, cut, h);
    renderer.render(state.a.scene, camera);
    renderer.setScissor(cut, 0, w - cut, h);
    renderer.render(state.b.scene, camera);
    renderer.setScissorTest(false);
  } else {
    renderer.render(state.a.scene, camera);
  }
}

let last = performance.now();
function loop(now) {
  if (state.walk) walk(Math.min(0.1, (now - last) / 1000));
  else controls.update();
  last = now;
  render();
  // performance.now() counts from navigation: the time to the first frame drawn.
  if (state.firstFrameSeconds === undefined) state.firstFrameSeconds = performance.now() / 1000;
  requestAnimationFrame(loop);
}

async function loadBakes() {
  const bakes = await (await fetch('/api/bakes')).json();
  const a = await loadBake(bakes[0]);
  // B is shown at A's exposure: each bake's own would make a brighter design look the same.
  const b = bakes[1] ? await loadBake(bakes[1], a.record.display_exposure) : null;
  return { bakes, a, b };
}

async function start() {
  Object.assign(state, await loading);
  $('title').textContent = `radbake view: ${state.bakes.map((b) => b.folder).join(' | ')}`;
  resize();
  const cameras = $('camera');
  state.a.gltf.cameras.forEach((c, k) => cameras.add(new Option(c.name || `camera ${k}`, String(k))));
  const view = state.a.bake.report.display?.camera_view;
  if (!state.a.gltf.cameras.length && view) cameras.add(new Option(view.in_room ? 'in the room' : 'the model', '-2'));
  firstView();
  cameras.value = state.a.gltf.cameras.length ? '0' : view ? '-2' : '-1';
  cameras.addEventListener('change', () => {
    const k = Number(cameras.value);
    if (k === -2) useView(view);
    else if (k < 0) frame(state.a.scene);
    else useCamera(state.a.gltf.cameras[k]);
  });
  // The baked light is drawn from here on; the rest waits for the EXR pages.
  requestAnimationFrame(loop);
  for (const bake of [state.a, state.b]) if (bake) bake.pages = await bake.pagesLoading;
  setupMaterials();
  exposureFromTheData();
  const modes = $('mode');
  if (daylightReference() > 0) modes.add(new Option('daylight factor', 'daylight'));
  if (state.a.sensors) modes.add(new Option('sensors (lux)', 'sensors'));
  if (state.b) {
    if (sameLayout(state.a, state.b)) modes.add(new Option('difference B − A', 'difference'));
    else $('title').textContent += ' (pages laid out differently: no difference)';
    $('compare-row').style.display = 'block';
  }
  for (const id of ['mode', 'scale', 'max', 'ev']) $(id).addEventListener('input', () => { state.mode = modes.value; applyMode(); });
  $('split').addEventListener('input', () => { state.split = Number($('split').value); });
  $('walk').addEventListener('change', () => { state.walk = $('walk').checked; controls.enabled = !state.walk; });
  if (state.a.probes) {
    $('probes-row').style.display = 'block';
    $('probes').addEventListener('change', () => { state.a.probes.visible = $('probes').checked; });
  }
  $('screenshot').addEventListener('click', () => {
    const link = document.createElement('a');
    link.download = 'radbake_view.png';
    link.href = canvas.toDataURL('image/png');
    link.click();
  });
  applyMode();
  state.loadSeconds = (performance.now() - started) / 1000;
}

// For tests and scripts.
const ready = start();
window.radbakeView = {
  ready,
  loadSeconds: () => state.loadSeconds,
  useCamera: (k) => {  // the glTF's camera k; -1 the whole scene framed; else the first view
    if (state.a.gltf.cameras[k]) useCamera(state.a.gltf.cameras[k]);
    else if (k === -1) frame(state.a.scene);
    else firstView();
    render();
  },
  evRange: () => [Number($('ev').min), Number($('ev').max), Number($('ev').value)],
  firstFrameSeconds: () => state.firstFrameSeconds,
  setMode: (mode, options = {}) => {
    $('mode').value = mode;
    state.mode = mode;
    if (options.scale) $('scale').value = options.scale;
    if (options.max !== undefined) $('max').value = String(options.max);
    if (options.compare) $('compare').value = options.compare;
    if (options.split !== undefined) state.split = options.split;
    if (options.ev !== undefined) $('ev').value = options.ev === 'lowest' ? $('ev').min : options.ev === 'highest' ? $('ev').max : String(options.ev);
    if (options.camera !== undefined) window.radbakeView.useCamera(options.camera);
    if (options.walk !== undefined) {
      $('walk').checked = options.walk;
      state.walk = options.walk;
      controls.enabled = !options.walk;
    }
    applyMode();
    render();
    return state.scale;
  },
  pixel: (x, y) => {
    const gl = renderer.getContext();
    const out = new Uint8Array(4);
    gl.readPixels(x, canvas.height - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return Array.from(out.slice(0, 3));
  },
  pick,
  cameraPosition: () => camera.position.toArray(),
  // The light probes: shown or hidden; how many; where probe k is drawn (CSS pixels) and its position.
  showProbes: (on) => {
    $('probes').checked = on;
    if (state.a.probes) state.a.probes.visible = on;
    render();
    return state.a.probes ? state.a.probes.children.length : 0;
  },
  probe: (k) => {
    const sphere = state.a.probes.children[k];
    const p = sphere.position.clone().project(camera);
    return { x: (p.x + 1) / 2 * canvas.clientWidth, y: (1 - p.y) / 2 * canvas.clientHeight, position: sphere.position.toArray() };
  },
  // Where sensor k is drawn, in CSS pixels (x right, y down), and its reading.
  sensor: (k) => {
    const p = new THREE.Vector3().fromBufferAttribute(state.a.sensors.points.geometry.attributes.position, k).project(camera);
    return { x: (p.x + 1) / 2 * canvas.clientWidth, y: (1 - p.y) / 2 * canvas.clientHeight, lux: state.a.sensors.lux[k] };
  },
};

// The display file (NAME_display.glb) in three.js's stock GLTFLoader, no lights, three.js's
// defaults (sRGB output, NoToneMapping), in Debian's headless Chromium: the back wall, the red wall
// and the floor show the display values radbake's own numbers give (the EXR page, the engine file's
// materials, extras.radbake.display_exposure), within 5%; the same after `gltf-transform optimize`
// and after `gltfpack` with default flags.
// usage: node tests/web/display_file.test.mjs --bake DIR --work DIR
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { openRenderer } from '../../web/render/render.mjs';
import { pixelToLinear } from '../../web/render/expect.mjs';
import {
  args, compare, displayFile, expectations, fmt, loadBake, luminance, run, NEAR_CAMERA, SIZE, SURFACES,
  SURFACE_PIXELS,
} from './support.mjs';

const { work, engine } = args();
const bake = await loadBake(engine);
const display = displayFile(bake, engine);
let renderer, expected;

before(async () => {
  renderer = await openRenderer();
  // The engine file's raycast says what each pixel sees (material, TEXCOORD_1); the render mode
  // does not matter for that.
  const engineView = await renderer.render({ file: engine, mode: 'plugin', camera: NEAR_CAMERA, width: SIZE, height: SIZE, points: SURFACE_PIXELS });
  expected = expectations(bake, engineView);
});

after(async () => {
  if (renderer) await renderer.close();
});

// Renders FILE with the stock loader and checks every surface pixel against the expectation.
async function checkStock(t, file, label, { meshopt = false, pointTolerance = 0.001 } = {}) {
  const shot = path.join(work, `display_${label}.png`);
  const r = await renderer.render({ file, mode: 'stock', camera: NEAR_CAMERA, width: SIZE, height: SIZE, points: SURFACE_PIXELS, out: shot, meshopt });
  assert.deepEqual(r.consoleErrors, [], 'the page logged errors');
  assert.deepEqual(r.lights, [], 'the display file carries no lights');
  for (const m of r.materials) assert.equal(m.type, 'MeshBasicMaterial', `material ${m.name} is not unlit (KHR_materials_unlit)`);
  const failures = [];
  let worstLum = 0;
  r.points.forEach((p, i) => {
    const e = expected[i];
    // The same surface point as in the engine file (the display file is world-space geometry).
    assert.ok(p.hit, `pixel ${p.x},${p.y} sees nothing`);
    const moved = Math.hypot(...p.hit.point.map((v, c) => v - e.point[c]));
    assert.ok(moved < pointTolerance, `pixel ${p.x},${p.y} sees a point ${moved.toFixed(4)} m from the engine file's`);
    const c = compare(p.rgb, e.linear);
    const lumErr = Math.abs(luminance(pixelToLinear(p.rgb)) / luminance(e.linear) - 1);
    worstLum = Math.max(worstLum, lumErr);
    t.diagnostic(`${label} ${e.object} (${p.x},${p.y}): got ${fmt(p.rgb)} expected ${fmt(e.linear.map((v) => 255 * (v <= 0.0031308 ? v * 12.92 : 1.055 * v ** (1 / 2.4) - 0.055)))} sRGB; luminance ${(lumErr * 100).toFixed(2)}%, worst channel ${(c.worst * 100).toFixed(2)}%`);
    if (!c.ok) failures.push(`${e.object} (${p.x},${p.y}) ${fmt(p.rgb)}: ${c.detail.map((d) => `${d.got.toFixed(4)} vs ${d.expected.toFixed(4)} ±${d.bound.toFixed(4)}`).join(', ')}`);
  });
  t.diagnostic(`${label}: worst luminance difference ${(worstLum * 100).toFixed(2)}% over ${r.points.length} pixels; screenshot ${shot}; ${r.ms.load.toFixed(0)} ms load, ${r.ms.render.toFixed(0)} ms render`);
  assert.deepEqual(failures, [], `pixels outside 5% (+1 sRGB code) of the EXR's display value`);
  return r;
}

test('the expected pixels see the surfaces they are meant to', () => {
  for (const [object, { material, pixels }] of Object.entries(SURFACES)) {
    for (const [x, y] of pixels) {
      const e = expected.find((v) => v.x === x && v.y === y);
      assert.equal(e.object, object, `pixel ${x},${y}`);
      assert.equal(e.material, material, `pixel ${x},${y}`);
      // Lit: the comparison means something only where the wall has light and is not clipped.
      assert.ok(Math.max(...e.linear) > 0.05 && Math.max(...e.linear) < 0.98, `pixel ${x},${y} expected ${e.linear}`);
    }
  }
});

test('display file, stock GLTFLoader, no lights: within 5% of the EXR', { skip: display === null && 'the engine file names no display file' }, async (t) => {
  await checkStock(t, display, 'stock');
});

test('display file after gltf-transform optimize (default flags)', { skip: display === null && 'no display file' }, async (t) => {
  const out = path.join(work, 'display_optimize.glb');
  run('gltf-transform', ['optimize', display, out]);
  // optimize's default --compress meshopt writes EXT_meshopt_compression (required): three.js reads it
  // with the decoder three.js ships (loader.setMeshoptDecoder), as any three.js app loading such files.
  // Quantized positions (16 bits over the box) move the seen point by well under 1 mm.
  await checkStock(t, out, 'optimize', { meshopt: true, pointTolerance: 0.002 });
});

test('display file after gltfpack (default flags)', { skip: display === null && 'no display file' }, async (t) => {
  const out = path.join(work, 'display_gltfpack.glb');
  run('gltfpack', ['-i', display, '-o', out]);
  // gltfpack's default quantization (KHR_mesh_quantization, 14-bit positions, 12-bit UVs with a
  // KHR_texture_transform) is read by the stock loader.
  await checkStock(t, out, 'gltfpack', { pointTolerance: 0.002 });
});

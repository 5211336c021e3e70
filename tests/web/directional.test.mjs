// Directional lightmaps in three.js: a floor whose normal map has stripes tilted toward
// and away from a low sun, baked with `--directional sh`, shows its stripes through the MOZ_lightmap
// plugin (web/radbake-lightmap.js) and in the display file (NAME_display.glb, stock GLTFLoader), in
// Debian's headless Chromium; baked without, it is flat in both.
// usage: node tests/web/directional.test.mjs --radbake BIN --work DIR
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { openRenderer } from '../../web/render/render.mjs';
import { pixelToLinear } from '../../web/render/expect.mjs';
import { SOURCE_DIR } from './support.mjs';

const argv = process.argv.slice(2);
const option = (name) => path.resolve(argv[argv.indexOf(name) + 1]);
const radbake = option('--radbake'), work = option('--work');
mkdirSync(work, { recursive: true });
const FIXTURE = path.join(SOURCE_DIR, 'tests/fixtures/normal_mapped_floor.gltf');

function bake(name, extra) {
  const out = path.join(work, name);
  execFileSync(radbake, ['bake', FIXTURE, '-o', out, '--quiet', '--max-page-size', '64', ...extra], { stdio: 'pipe' });
  return path.join(out, 'normal_mapped_floor.gltf');
}

// Straight down on the floor, its u (world +X) across the image; pixels along the middle row.
const CAMERA = { position: [0, 2.2, 0.0001], target: [0, 0, 0], fov: 40 };
const ROW = Array.from({ length: 80 }, (_, i) => [48 + 2 * i, 128]);
let renderer, plain, directional, plainDisplay, directionalDisplay;

const luminance = (rgb) => { const [r, g, b] = pixelToLinear(rgb); return 0.2126 * r + 0.7152 * g + 0.0722 * b; };

before(async () => {
  renderer = await openRenderer();
  const shoot = (file, name) => renderer.render({ file, mode: 'plugin', camera: CAMERA, width: 256, height: 256,
    points: ROW, out: path.join(work, name) });
  const plainFile = bake('plain', []), directionalFile = bake('sh', ['--directional', 'sh']);
  plain = await shoot(plainFile, 'plain.png');
  directional = await shoot(directionalFile, 'directional.png');
  const display = (file, name) => renderer.render({ file: file.replace(/\.gltf$/, '_display.glb'), mode: 'stock',
    camera: CAMERA, width: 256, height: 256, points: ROW, out: path.join(work, name) });
  plainDisplay = await display(plainFile, 'plain_display.png');
  directionalDisplay = await display(directionalFile, 'directional_display.png');
});

after(async () => { if (renderer) await renderer.close(); });

test('the plugin reads the directional pages, and nothing goes wrong in the page', () => {
  assert.deepEqual(directional.consoleErrors, []);
  assert.equal(directional.userData.radbakeDirectionalMaterials, 1);
  assert.equal(plain.userData.radbakeDirectionalMaterials, 0);
  for (const p of directional.points) assert.equal(p.hit && p.hit.object, 'floor');
});

const stats = (shot) => {
  const l = shot.points.map((p) => luminance(p.rgb));
  const mean = l.reduce((a, b) => a + b, 0) / l.length;
  return { mean, min: Math.min(...l), max: Math.max(...l) };
};

test('the normal map shows under directional lightmaps and not under the plain one', () => {
  const p = stats(plain), d = stats(directional);
  // Plain: one irradiance over the whole floor (E_perp cos 60), one grey; only 8-bit rounding varies.
  assert.ok(p.max - p.min < 0.02 * p.mean, `plain floor not flat: ${JSON.stringify(p)}`);
  // Directional: stripes turned 35 degrees toward the sun take E_perp cos 25 (1.8 times the flat
  // floor's cos 60), those turned away cos 95 (nothing); pixels straddling a stripe's edge lie
  // between, so the bounds are loose: brightest over 1.4 times the plain floor, darkest under 0.3.
  assert.ok(d.max > 1.4 * p.mean, `bright stripes: ${JSON.stringify({ d, p })}`);
  assert.ok(d.min < 0.3 * p.mean, `dark stripes: ${JSON.stringify({ d, p })}`);
});

test('the display file shows the stripes too, pre-lit for each texel\'s mapped normal', () => {
  const p = stats(plainDisplay), d = stats(directionalDisplay);
  assert.deepEqual(directionalDisplay.consoleErrors, []);
  // The same bounds as through the plugin: the pre-lit pages evaluate the same L1 light.
  assert.ok(p.max - p.min < 0.02 * p.mean, `plain display not flat: ${JSON.stringify(p)}`);
  assert.ok(d.max > 1.4 * p.mean, `bright stripes: ${JSON.stringify({ d, p })}`);
  assert.ok(d.min < 0.3 * p.mean, `dark stripes: ${JSON.stringify({ d, p })}`);
});

// The MOZ_lightmap plugin (web/radbake-lightmap.js) on the engine file (NAME.gltf) in three.js, in
// Debian's headless Chromium: PBR materials plus the lightmap show what the display file shows
// (within 5%), at the exposure the file carries; baked punctual lights are not drawn again; the
// engine file keeps its lightmap through `gltf-transform optimize` with radbake's config.
// usage: node tests/web/plugin.test.mjs --bake DIR --work DIR --share BUILD/share/radbake
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { openRenderer } from '../../web/render/render.mjs';
import { pixelToLinear } from '../../web/render/expect.mjs';
import {
  args, compare, displayFile, expectations, fmt, loadBake, luminance, run, NEAR_CAMERA, SIZE, SOURCE_DIR, SURFACE_PIXELS, WEB_DIR,
} from './support.mjs';

const { work, engine } = args();
const bake = await loadBake(engine);
const display = displayFile(bake, engine);
let renderer, expected, pluginView;

const near = (file, extra = {}) =>
  renderer.render({ file, mode: 'plugin', camera: NEAR_CAMERA, width: SIZE, height: SIZE, points: SURFACE_PIXELS, ...extra });

before(async () => {
  renderer = await openRenderer();
  pluginView = await near(engine, { out: path.join(work, 'plugin_near.png') });
  expected = expectations(bake, pluginView);
});

after(async () => {
  if (renderer) await renderer.close();
});

// A copy of the engine file with its JSON changed by EDIT, beside copies of its buffers and images.
function variant(name, edit) {
  const dir = path.join(work, name);
  mkdirSync(dir, { recursive: true });
  const json = structuredClone(bake.json);
  for (const item of [...(json.buffers || []), ...(json.images || [])]) {
    if (item.uri && !item.uri.startsWith('data:')) copyFileSync(path.join(path.dirname(engine), decodeURIComponent(item.uri)), path.join(dir, decodeURIComponent(item.uri)));
  }
  edit(json);
  const file = path.join(dir, 'cornell_box.gltf');
  writeFileSync(file, JSON.stringify(json));
  return file;
}

test('the plugin sets the lightmap from MOZ_lightmap at the file\'s display exposure', () => {
  assert.deepEqual(pluginView.consoleErrors, []);
  assert.ok(bake.exposure > 0, 'the engine file has extras.radbake.display_exposure');
  assert.deepEqual(pluginView.userData.radbakeExposure, { value: bake.exposure, source: 'extras.radbake.display_exposure' });
  const lit = bake.json.materials.filter((m) => m.extensions && m.extensions.MOZ_lightmap);
  assert.ok(lit.length > 0);
  for (const def of lit) {
    const m = pluginView.materials.find((x) => x.name === def.name);
    assert.ok(m, `material ${def.name} is in the scene`);
    assert.equal(m.type, 'MeshStandardMaterial', 'PBR material kept');
    assert.equal(m.lightMap, true, `${def.name} has a light map`);
    assert.equal(m.lightMapChannel, def.extensions.MOZ_lightmap.texCoord, `${def.name} reads the lightmap from TEXCOORD_${def.extensions.MOZ_lightmap.texCoord}`);
    // lightMapIntensity turns the page (E = srgb_to_linear(png) × intensity lux) into display units.
    assert.ok(Math.abs(m.lightMapIntensity - def.extensions.MOZ_lightmap.intensity * bake.exposure) < 1e-9 * m.lightMapIntensity);
  }
});

test('plugin on the engine file: within 5% of the EXR and of the display file at the same pixels', async (t) => {
  const failures = [];
  let worstLum = 0, worstDisplayLum = 0;
  const displayView = display ? await near(display, { mode: 'stock' }) : null;
  pluginView.points.forEach((p, i) => {
    const e = expected[i];
    const c = compare(p.rgb, e.linear);
    worstLum = Math.max(worstLum, Math.abs(luminance(pixelToLinear(p.rgb)) / luminance(e.linear) - 1));
    if (!c.ok) failures.push(`vs EXR: ${e.object} (${p.x},${p.y}) ${fmt(p.rgb)}: ${c.detail.map((d) => `${d.got.toFixed(4)} vs ${d.expected.toFixed(4)} ±${d.bound.toFixed(4)}`).join(', ')}`);
    if (displayView) {
      const d = displayView.points[i];
      // Both are 8-bit renders of the same value (the display path rounds twice, the plugin path
      // twice: its page PNG and the frame buffer), so 2 codes on top of the 5%.
      const cd = compare(p.rgb, pixelToLinear(d.rgb), { codes: 2 });
      const lum = Math.abs(luminance(pixelToLinear(p.rgb)) / luminance(pixelToLinear(d.rgb)) - 1);
      worstDisplayLum = Math.max(worstDisplayLum, lum);
      t.diagnostic(`${e.object} (${p.x},${p.y}): plugin ${fmt(p.rgb)}, display ${fmt(d.rgb)}; luminance ${(lum * 100).toFixed(2)}% apart`);
      if (!cd.ok) failures.push(`vs display: ${e.object} (${p.x},${p.y}) plugin ${fmt(p.rgb)} display ${fmt(d.rgb)}`);
    }
  });
  t.diagnostic(`plugin vs EXR: worst luminance difference ${(worstLum * 100).toFixed(2)}%`);
  if (displayView) t.diagnostic(`plugin vs display file: worst luminance difference ${(worstDisplayLum * 100).toFixed(2)}%`);
  assert.deepEqual(failures, []);
  if (!display) t.skip('no display file to compare with (checked against the EXR only)');
});

test("lambert: false leaves three.js's specular split, which darkens the light map", async (t) => {
  const split = await near(engine, { pluginOptions: { lambert: false } });
  assert.deepEqual(split.consoleErrors, []);
  let least = Infinity, most = 0;
  split.points.forEach((p, i) => {
    const darker = 1 - luminance(pixelToLinear(p.rgb)) / luminance(pixelToLinear(pluginView.points[i].rgb));
    least = Math.min(least, darker);
    most = Math.max(most, darker);
  });
  t.diagnostic(`three.js's own split: ${(least * 100).toFixed(2)}% to ${(most * 100).toFixed(2)}% darker than the Lambertian light map`);
  // F0 = 0.04 at roughness 1 takes a few percent: the patch is what the comparison above relies on.
  assert.ok(least > 0.005, `every pixel is darker without the patch (least ${least})`);
});

test('baked punctual lights are not drawn again; an unbaked one is', async () => {
  // A 300 cd point light in the middle of the box roughly doubles the walls' light: it shows.
  const withLight = (baked) => (json) => {
    json.extensionsUsed = [...new Set([...(json.extensionsUsed || []), 'KHR_lights_punctual'])];
    json.extensions = { ...(json.extensions || {}), KHR_lights_punctual: { lights: [{ name: 'lamp', type: 'point', intensity: 300, ...(baked ? { extras: { radbake: { baked: true } } } : {}) }] } };
    json.nodes.push({ name: 'lamp node', translation: [0.278, 0.3, 0.28], extensions: { KHR_lights_punctual: { light: 0 } } });
    json.scenes[json.scene || 0].nodes.push(json.nodes.length - 1);
  };
  const baked = await near(variant('baked_light', withLight(true)));
  const unbaked = await near(variant('unbaked_light', withLight(false)));
  const kept = await near(variant('baked_light', withLight(true)), { pluginOptions: { bakedLights: 'keep' } });
  for (const r of [baked, unbaked, kept]) assert.deepEqual(r.consoleErrors, []);
  assert.deepEqual(baked.lights, [], 'the baked light is removed');
  assert.deepEqual(baked.userData.radbakeBakedLights, ['lamp']);
  assert.equal(unbaked.lights.length, 1, 'an unbaked light stays');
  assert.equal(kept.lights.length, 1, "bakedLights: 'keep' keeps it");
  assert.deepEqual(kept.lights[0].userData.radbake, { baked: true }, 'GLTFLoader exposes the marker as light.userData.radbake');
  baked.points.forEach((p, i) => {
    // Same pixels as without any light (the frame is deterministic: no code may move).
    assert.deepEqual(p.rgb, pluginView.points[i].rgb, `pixel ${p.x},${p.y} changed with a baked light in the file`);
    const lit = luminance(pixelToLinear(unbaked.points[i].rgb)), plain = luminance(pixelToLinear(p.rgb));
    assert.ok(lit > 1.2 * plain, `pixel ${p.x},${p.y}: the unbaked light shows (${lit.toFixed(3)} vs ${plain.toFixed(3)})`);
    assert.deepEqual(kept.points[i].rgb, unbaked.points[i].rgb, `pixel ${p.x},${p.y}: a kept baked light draws as an unbaked one`);
  });
});

test('exposure: options.exposure wins; without display_exposure, pi / intensity', async () => {
  const lit = bake.json.materials.find((m) => m.extensions && m.extensions.MOZ_lightmap);
  const intensity = lit.extensions.MOZ_lightmap.intensity;
  const option = await near(engine, { pluginOptions: { exposure: 1e-3 }, points: [] });
  assert.deepEqual(option.userData.radbakeExposure, { value: 1e-3, source: 'options.exposure' });
  assert.ok(Math.abs(option.materials.find((m) => m.name === lit.name).lightMapIntensity - intensity * 1e-3) < 1e-9);
  const old = await near(variant('no_exposure', (json) => { delete json.extras.radbake.display_exposure; }), { points: [] });
  assert.equal(old.userData.radbakeExposure.source, 'fallback: pi / intensity');
  assert.ok(Math.abs(old.materials.find((m) => m.name === lit.name).lightMapIntensity - Math.PI) < 1e-9);
});

// The recipe as a user runs it: the gltf-transform CLI web/ pins, and the same version installed
// apart from web/ as npm installs it anywhere (tests/tools/node_modules), run from a folder of its
// own with the config from the build's share folder (as installed; docs/install.md). Before the config
// was built on the CLI's own core, the apart CLI kept MOZ_lightmap but pruned TEXCOORD_0 and TEXCOORD_1: the config's extension was
// built on web/'s copy of @gltf-transform/core, not the CLI's.
const share = path.resolve(process.argv[process.argv.indexOf('--share') + 1]);
const recipes = [
  { name: 'web', cli: path.join(WEB_DIR, 'node_modules', '.bin', 'gltf-transform'), config: path.join(WEB_DIR, 'gltf-transform.config.mjs') },
  { name: 'apart', cli: path.join(SOURCE_DIR, 'tests', 'tools', 'node_modules', '.bin', 'gltf-transform'), config: path.join(share, 'web', 'gltf-transform.config.mjs') },
];
for (const recipe of recipes) {
  test(`engine file through gltf-transform optimize (the CLI ${recipe.name === 'web' ? "web/ pins" : 'installed apart'}) keeps its lightmap`, async (t) => {
    assert.ok(process.argv.includes('--share'), 'no --share DIR given');
    const out = path.join(work, `engine_optimize_${recipe.name}.glb`);
    const cwd = path.join(work, `cli_${recipe.name}`);
    mkdirSync(cwd, { recursive: true });
    execFileSync(recipe.cli, ['optimize', '--config', recipe.config, engine, out], { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
    const r = await near(out, { meshopt: true, out: path.join(work, `plugin_optimize_${recipe.name}.png`) });
    assert.deepEqual(r.consoleErrors, []);
    assert.ok(r.materials.length > 0 && r.materials.every((m) => m.lightMap), 'every material kept its lightmap');
    const failures = [];
    r.points.forEach((p, i) => {
      const c = compare(p.rgb, expected[i].linear);
      t.diagnostic(`${expected[i].object} (${p.x},${p.y}): ${fmt(p.rgb)}, worst channel ${(c.worst * 100).toFixed(2)}%`);
      if (!c.ok) failures.push(`${expected[i].object} (${p.x},${p.y}) ${fmt(p.rgb)}`);
    });
    assert.deepEqual(failures, []);
  });
}

// What the README says about gltfpack and the engine file, checked so the text cannot drift:
// gltfpack drops MOZ_lightmap whatever the flags (it writes only extensions it knows), and keeps
// TEXCOORD_1 with -kv. Without -vtf an unreferenced UV set is quantized with no texture transform
// to undo it (the UVs come out 16 times too small); -vtf stores floats, rounded to -vt bits
// (12 by default: 1/4096, a texel of a 4096 page), so -vt 16. (-kv -noq keeps everything as float.)
test('engine file through gltfpack -kv -vtf -vt 16: TEXCOORD_1 kept (the same UVs), MOZ_lightmap dropped', async () => {
  const { NodeIO } = await import('../../web/node_modules/@gltf-transform/core/dist/index.js');
  const { ALL_EXTENSIONS } = await import('../../web/node_modules/@gltf-transform/extensions/dist/index.js');
  const out = path.join(work, 'engine_gltfpack.glb');
  run('gltfpack', ['-i', engine, '-o', out, '-kv', '-vtf', '-vt', '16']);
  const io = new NodeIO().registerExtensions(ALL_EXTENSIONS);
  const vertices = async (file) => {
    const doc = await io.read(file);
    const list = [];
    for (const node of doc.getRoot().listNodes()) {
      if (!node.getMesh()) continue;
      const m = node.getWorldMatrix();
      for (const p of node.getMesh().listPrimitives()) {
        const pos = p.getAttribute('POSITION'), uv = p.getAttribute('TEXCOORD_1');
        assert.ok(uv, `a primitive of ${node.getName() || 'a node'} in ${path.basename(file)} has no TEXCOORD_1`);
        assert.equal(uv.getNormalized(), false, 'TEXCOORD_1 stays float');
        for (let i = 0; i < pos.getCount(); i++) {
          const [x, y, z] = pos.getElement(i, []);
          const w = [0, 1, 2].map((r) => m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r]);
          list.push({ w, uv: uv.getElement(i, []) });
        }
      }
    }
    return { doc, list };
  };
  const original = await vertices(engine);
  const packed = await vertices(out);
  assert.ok(packed.doc.getRoot().listMaterials().every((m) => !m.getExtension('MOZ_lightmap')), 'gltfpack kept MOZ_lightmap: update the README');
  for (const v of packed.list) {
    // 14-bit positions over the 0.56 m box: 0.1 mm; some original vertex at that place has this UV.
    const same = original.list.filter((o) => Math.hypot(...o.w.map((c, i) => c - v.w[i])) < 2e-4);
    assert.ok(same.some((o) => Math.abs(o.uv[0] - v.uv[0]) < 1e-5 && Math.abs(o.uv[1] - v.uv[1]) < 1e-5),
      `vertex at ${v.w.map((c) => c.toFixed(4))} has TEXCOORD_1 ${v.uv} that no original vertex there has`);
  }
});

// Shared by the browser tests (tests/web/*.test.mjs, registered in tests/CMakeLists.txt).
// Each test file takes: --bake DIR (radbake's output for the Cornell box, made by the ctest fixture
// web.bake_cornell_box) --work DIR (where it writes screenshots and pipeline outputs).
import { existsSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { execFileSync } from 'node:child_process';
import {
  codeWidth, displayLinear, pixelToLinear, radbakeExtras, readExr, readGltfJson, reflectance, sampleBilinear,
} from '../../web/render/expect.mjs';

export const SOURCE_DIR = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const WEB_DIR = path.join(SOURCE_DIR, 'web');
export const BIN = path.join(WEB_DIR, 'node_modules', '.bin');

export function args() {
  const a = process.argv.slice(2);
  const get = (name) => {
    const i = a.indexOf(name);
    if (i < 0 || i + 1 >= a.length) throw new Error(`missing ${name} DIR`);
    return path.resolve(a[i + 1]);
  };
  const bake = get('--bake'), work = get('--work');
  mkdirSync(work, { recursive: true });
  return { bake, work, engine: path.join(bake, 'cornell_box.gltf') };
}

export function run(tool, argv) {
  return execFileSync(path.join(BIN, tool), argv, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

// The Cornell box seen by its own camera (samples/cornell_box: at (0.278, 0.273, -0.8) looking +z,
// yfov 0.686 rad), 256 × 256. Pixels (x right, y down) at the middle of big flat surfaces, away
// from edges and the blocks; each names the node and material the ray through it must hit, so a
// moved camera or scene fails loudly instead of comparing another surface.
export const NEAR_CAMERA = { position: [0.278, 0.273, -0.8], target: [0.278, 0.273, 0.2], fov: (0.6860478808414068 * 180) / Math.PI };
export const SIZE = 256;
export const SURFACES = {
  back_wall: { material: 'white', pixels: [[128, 62], [170, 70], [150, 95]] },
  left_wall_red: { material: 'red', pixels: [[25, 100], [25, 150], [35, 60]] },
  floor: { material: 'white', pixels: [[40, 235], [100, 238], [210, 232]] },
};
export const SURFACE_PIXELS = Object.values(SURFACES).flatMap((s) => s.pixels);

/** The bake's numbers: engine JSON, its extras.radbake, the EXR pages, the display exposure. */
export async function loadBake(engine) {
  const json = await readGltfJson(engine);
  const radbake = radbakeExtras(json);
  if (!radbake) throw new Error(`${engine} has no extras.radbake`);
  const pages = await Promise.all(radbake.pages.map((p) => readExr(path.join(path.dirname(engine), p.exr))));
  return { json, radbake, pages, exposure: radbake.display_exposure };
}

/** The display file the engine file names (extras.radbake.display_file), or null when it names none. */
export function displayFile(bake, engine) {
  if (!bake.radbake.display_file) return null;
  const file = path.join(path.dirname(engine), bake.radbake.display_file);
  if (!existsSync(file)) throw new Error(`extras.radbake.display_file names ${file}, which is not there`);
  return file;
}

/**
 * Expected display value at each pixel, from a render of the engine file (its raycast hits say
 * which material and which TEXCOORD_1 each pixel sees): clamp(ρ × E(uv) / π × exposure), with E
 * bilinear from the EXR page as a LINEAR sampler reads it.
 */
export function expectations(bake, engineRender) {
  return engineRender.points.map((p) => {
    if (!p.hit) throw new Error(`pixel ${p.x},${p.y} sees nothing`);
    const material = bake.json.materials[p.hit.materialIndex];
    const lightmap = material.extensions && material.extensions.MOZ_lightmap;
    if (!lightmap) throw new Error(`pixel ${p.x},${p.y} sees material ${material.name} without MOZ_lightmap`);
    const page = bake.pages[bake.radbake.pages.findIndex((pg) => pg.texture === lightmap.index)];
    const uv = lightmap.texCoord === 1 ? p.hit.uv1 : p.hit.uv;
    const E = sampleBilinear(page, uv[0], uv[1]);
    const rho = reflectance(bake.json, p.hit.materialIndex);
    return { x: p.x, y: p.y, object: p.hit.object, material: material.name, point: p.hit.point, irradiance: E, rho,
      linear: displayLinear(rho, E, bake.exposure) };
  });
}

/**
 * Compares a displayed pixel with its expected linear display value, per channel, in linear display
 * units: |got − expected| ≤ 5% × expected + `codes` × (one 8-bit sRGB code at the expected value).
 * The 5% bounds everything the pipeline could get wrong (exposure, intensity,
 * colour space, filtering, the viewer's shading); the code term bounds the rounding of the 8-bit
 * stages, which no viewer can avoid (a page PNG and the frame buffer: ±½ code each, so 1 code; it
 * matters for dark channels, where one code is more than 5%). Returns { ok, worst, detail }.
 */
export function compare(gotRgb, expectedLinear, { relative = 0.05, codes = 1 } = {}) {
  const got = pixelToLinear(gotRgb);
  let ok = true, worst = 0;
  const detail = got.map((g, c) => {
    const e = expectedLinear[c];
    const bound = relative * e + codes * codeWidth(e);
    const err = Math.abs(g - e);
    if (err > bound) ok = false;
    worst = Math.max(worst, e > 0 ? err / e : err);
    return { got: g, expected: e, bound, err };
  });
  return { ok, worst, detail };
}

/** Luminance (Rec. 709 weights) of linear RGB, for the summaries the tests print. */
export const luminance = (rgb) => 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];

export function fmt(rgb) {
  return `(${rgb.map((v) => (Math.round(v * 10) / 10).toString()).join(', ')})`;
}

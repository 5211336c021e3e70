// What a pixel should show, from radbake's own numbers: the EXR page (irradiance in lux), the
// engine file's materials (reflectance) and the file's exposure. Used by tests/web; no browser.
//   displayed linear value = clamp(reflectance × E / π × exposure, 0, 1), shown sRGB-encoded.
import { readFile } from 'node:fs/promises';
import { FloatType } from 'three';
import { EXRLoader } from 'three/examples/jsm/loaders/EXRLoader.js';
import { decodePng } from './png.mjs';

export const srgbToLinear = (s) => (s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4);
export const linearToSrgb = (l) => (l <= 0.0031308 ? l * 12.92 : 1.055 * l ** (1 / 2.4) - 0.055);
const clamp01 = (x) => Math.min(1, Math.max(0, x));

/** The JSON of a .gltf or .glb. */
export async function readGltfJson(file) {
  const bytes = await readFile(file);
  if (bytes.readUInt32LE(0) === 0x46546c67) return JSON.parse(bytes.toString('utf8', 20, 20 + bytes.readUInt32LE(12)));
  return JSON.parse(bytes.toString('utf8'));
}

/** radbake's description of the bake: root extras.radbake (asset.extras.radbake when the root extras is not an object). */
export function radbakeExtras(json) {
  if (json.extras && typeof json.extras === 'object' && json.extras.radbake) return json.extras.radbake;
  return (json.asset && json.asset.extras && json.asset.extras.radbake) || null;
}

/** An EXR page as { width, height, data: Float32Array RGBA } with row 0 the image's top (glTF v = 0). */
export async function readExr(file) {
  const bytes = await readFile(file);
  const exr = new EXRLoader().setDataType(FloatType).parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
  const channels = exr.data.length / (exr.width * exr.height);
  // three.js's EXRLoader puts the file's last row first (a texture's origin is bottom-left): flip back.
  const data = new Float32Array(exr.width * exr.height * 4);
  for (let y = 0; y < exr.height; y++) {
    for (let x = 0; x < exr.width; x++) {
      const src = ((exr.height - 1 - y) * exr.width + x) * channels, dst = (y * exr.width + x) * 4;
      for (let c = 0; c < 4; c++) data[dst + c] = c < channels ? exr.data[src + c] : 1;
    }
  }
  return { width: exr.width, height: exr.height, data };
}

/** A PNG as { width, height, rgba } rows top first. */
export async function readPng(file) {
  return decodePng(await readFile(file));
}

/** Bilinear sample at glTF UV (u, v) (v = 0 at the image's top), clamp to edge, as a LINEAR sampler does. */
export function sampleBilinear(image, u, v) {
  const values = image.data || image.rgba;
  const x = u * image.width - 0.5, y = v * image.height - 0.5;
  const x0 = Math.floor(x), y0 = Math.floor(y), fx = x - x0, fy = y - y0;
  const at = (xi, yi, c) => {
    const cx = Math.min(image.width - 1, Math.max(0, xi)), cy = Math.min(image.height - 1, Math.max(0, yi));
    return values[(cy * image.width + cx) * 4 + c];
  };
  return [0, 1, 2].map((c) =>
    (1 - fy) * ((1 - fx) * at(x0, y0, c) + fx * at(x0 + 1, y0, c)) + fy * ((1 - fx) * at(x0, y0 + 1, c) + fx * at(x0 + 1, y0 + 1, c)));
}

/**
 * A material's diffuse reflectance as radbake reads it: baseColorFactor × (1 − metallicFactor)
 * (glTF defaults: factor 1, metallic 1). Textured or vertex-coloured materials need the texel
 * and are refused here, so a test cannot silently compare against the wrong value.
 */
export function reflectance(json, materialIndex) {
  const m = json.materials[materialIndex];
  const pbr = m.pbrMetallicRoughness || {};
  if (pbr.baseColorTexture) throw new Error(`material ${materialIndex} (${m.name}) has a base colour texture: reflectance needs its texel`);
  const factor = pbr.baseColorFactor || [1, 1, 1, 1];
  const metallic = pbr.metallicFactor !== undefined ? pbr.metallicFactor : 1;
  return factor.slice(0, 3).map((f) => Math.min(0.999, f * (1 - metallic)));
}

/** The linear display value (each channel clipped to [0, 1]) of a Lambertian surface under E lux. */
export function displayLinear(rho, irradiance, exposure) {
  return rho.map((r, c) => clamp01((r * irradiance[c] / Math.PI) * exposure));
}

/** The width, in linear display units, of one 8-bit sRGB code at linear value l. */
export function codeWidth(l) {
  const s = linearToSrgb(clamp01(l)) * 255;
  return srgbToLinear(Math.min(255, s + 0.5) / 255) - srgbToLinear(Math.max(0, s - 0.5) / 255);
}

/** Displayed 8-bit sRGB pixel (0..255) to linear display value. */
export const pixelToLinear = (rgb) => rgb.map((v) => srgbToLinear(v / 255));

#!/usr/bin/env node
// The render harness: a glTF file seen by three.js in Debian's headless Chromium.
//
// As a library (one browser launch for many renders):
//   import { openRenderer } from './render.mjs';
//   const r = await openRenderer();
//   const shot = await r.render({ file: 'out/cornell_box/cornell_box_display.glb', mode: 'stock',
//     camera: { position: [0.278, 0.273, -0.8], target: [0.278, 0.273, 0.28], fov: 39.3 },
//     width: 256, height: 256, points: [[128, 64]], patch: 1, out: 'shot.png' });
//   (background: [r, g, b] in 0..1 clears to that colour instead of black)
//   shot.points[0].rgb, shot.points[0].hit.object, shot.consoleErrors
//   await r.close();
//
// From the shell (prints one JSON object; exits 1 when the page logged an error):
//   node web/render/render.mjs FILE [--mode stock|plugin] [--camera X,Y,Z/TX,TY,TZ/FOV | --camera gltf]
//       [--size 256x256] [--out shot.png] [--points "X,Y;X,Y"] [--patch R] [--exposure E]
//       [--mipmaps as-written|force] [--meshopt]
//
// Modes: `stock` is the stock GLTFLoader with three.js's defaults (no lights added, NoToneMapping,
// sRGB output); `plugin` registers web/radbake-lightmap.js for MOZ_lightmap. Everything is served
// from this machine: the file's folder, three.js from web/node_modules and the plugin, by node's
// http module on 127.0.0.1; Chromium is Debian's /usr/bin/chromium (playwright-core never
// downloads a browser), WebGL on SwiftShader (software), so no GPU is needed.
import { createServer } from 'node:http';
import { createReadStream } from 'node:fs';
import { readFile, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { encodePng } from './png.mjs';

const WEB_DIR = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const THREE_DIR = path.join(WEB_DIR, 'node_modules', 'three');

// WebGL in headless Chromium without a GPU: ANGLE on SwiftShader. Chromium refuses the software
// fallback for WebGL unless told it is wanted (--enable-unsafe-swiftshader); --ignore-gpu-blocklist
// keeps a blocklisted driver from turning WebGL off.
export const CHROMIUM_ARGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
  '--disable-gpu-sandbox', '--no-first-run', '--disable-extensions'];
export const CHROMIUM_PATH = process.env.RADBAKE_CHROMIUM || '/usr/bin/chromium';

const TYPES = {
  '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
  '.gltf': 'model/gltf+json', '.glb': 'model/gltf-binary', '.bin': 'application/octet-stream',
  '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.webp': 'image/webp', '.ktx2': 'image/ktx2',
  '.wasm': 'application/wasm',
};

// Serves web/render (the page), web/radbake-lightmap.js, three.js and mounted folders, nothing else.
async function startServer() {
  const mounts = new Map(); // id -> folder
  const routes = [
    ['/render/', path.join(WEB_DIR, 'render')],
    ['/web/', WEB_DIR],
    ['/three/', THREE_DIR],
  ];
  const server = createServer(async (req, res) => {
    try {
      const url = new URL(req.url, 'http://localhost');
      if (url.pathname === '/favicon.ico') { res.writeHead(204); res.end(); return; }
      const pathname = decodeURIComponent(url.pathname);
      let root = null, rest = null;
      const m = /^\/files\/(\d+)\/(.*)$/.exec(pathname);
      if (m && mounts.has(m[1])) [root, rest] = [mounts.get(m[1]), m[2]];
      else for (const [prefix, dir] of routes) if (pathname.startsWith(prefix)) { [root, rest] = [dir, pathname.slice(prefix.length)]; break; }
      if (root === null) throw Object.assign(new Error('not found'), { status: 404 });
      const file = path.resolve(root, rest);
      if (file !== root && !file.startsWith(root + path.sep)) throw Object.assign(new Error('outside'), { status: 403 });
      if (root === WEB_DIR && path.relative(WEB_DIR, file).startsWith('node_modules')) throw Object.assign(new Error('not served'), { status: 403 });
      const info = await stat(file);
      if (!info.isFile()) throw Object.assign(new Error('not a file'), { status: 404 });
      res.writeHead(200, { 'Content-Type': TYPES[path.extname(file).toLowerCase()] || 'application/octet-stream',
        'Content-Length': info.size, 'Cache-Control': 'no-store' });
      createReadStream(file).pipe(res);
    } catch (e) {
      res.writeHead(e.status || (e.code === 'ENOENT' ? 404 : 500), { 'Content-Type': 'text/plain' });
      res.end(String(e.message));
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const base = `http://127.0.0.1:${server.address().port}`;
  return {
    base,
    mount(folder) {
      const dir = path.resolve(folder);
      for (const [id, d] of mounts) if (d === dir) return `${base}/files/${id}/`;
      const id = String(mounts.size);
      mounts.set(id, dir);
      return `${base}/files/${id}/`;
    },
    close: () => new Promise((resolve) => server.close(resolve)),
  };
}

/** Mean RGB over the (2·patch+1)² pixels around (x, y), rows top first. */
export function pixelMean(image, x, y, patch = 0) {
  const sum = [0, 0, 0];
  let n = 0;
  for (let dy = -patch; dy <= patch; dy++) {
    for (let dx = -patch; dx <= patch; dx++) {
      const px = Math.min(image.width - 1, Math.max(0, x + dx)), py = Math.min(image.height - 1, Math.max(0, y + dy));
      const i = (py * image.width + px) * 4;
      for (let c = 0; c < 3; c++) sum[c] += image.rgba[i + c];
      n++;
    }
  }
  return sum.map((s) => s / n);
}

/** A camera from the file's first camera node (position and view direction, vertical fov). */
export async function gltfCamera(file) {
  let json;
  const bytes = await readFile(file);
  if (bytes.readUInt32LE(0) === 0x46546c67) { // 'glTF': a .glb, JSON chunk first
    const length = bytes.readUInt32LE(12);
    json = JSON.parse(bytes.toString('utf8', 20, 20 + length));
  } else json = JSON.parse(bytes.toString('utf8'));
  const node = (json.nodes || []).find((n) => n.camera !== undefined);
  if (!node) throw new Error(`${file} has no camera node: give --camera X,Y,Z/TX,TY,TZ/FOV`);
  const cam = json.cameras[node.camera];
  if (cam.type !== 'perspective') throw new Error('only perspective cameras');
  // World transform of the camera node is assumed to be its own TRS (a root node), as in the samples.
  const t = node.translation || [0, 0, 0];
  const [x, y, z, w] = node.rotation || [0, 0, 0, 1];
  // The camera looks down its local -Z: rotate (0, 0, -1) by the quaternion.
  const dir = [-(2 * (x * z + w * y)), -(2 * (y * z - w * x)), -(1 - 2 * (x * x + y * y))];
  // No zfar is glTF's infinite projection: a far plane ten million near planes away stands for it.
  const far = cam.perspective.zfar || cam.perspective.znear * 1e7;
  return { position: t, target: t.map((v, i) => v + dir[i]), fov: (cam.perspective.yfov * 180) / Math.PI, near: cam.perspective.znear, far };
}

export async function openRenderer({ executablePath = CHROMIUM_PATH, args = [] } = {}) {
  const server = await startServer();
  const browser = await chromium.launch({ executablePath, args: [...CHROMIUM_ARGS, ...args], headless: true });
  const context = await browser.newContext({ viewport: { width: 640, height: 480 }, deviceScaleFactor: 1 });

  // One page for all renders (three.js is fetched and compiled once); each render gets a fresh
  // canvas and WebGL context, and the console messages logged while it ran.
  const page = await context.newPage();
  let sink = { errors: [], warnings: [] };
  page.on('console', (msg) => {
    if (msg.type() === 'error') sink.errors.push(msg.text());
    else if (msg.type() === 'warning') sink.warnings.push(msg.text());
  });
  page.on('pageerror', (e) => sink.errors.push(`page error: ${e.message}`));
  // Chromium sometimes reports a fetch that three.js's FileLoader read to the end through a stream
  // reader as net::ERR_ABORTED; with a 200 response the loader had its bytes (a short body throws
  // in the loader), so that one is a warning. Any other failure is an error.
  page.on('requestfailed', (r) => {
    const text = `request failed: ${r.url()} ${r.failure() && r.failure().errorText}`;
    const target = sink;
    r.response().then((response) => {
      const delivered = response && response.ok() && r.failure() && r.failure().errorText === 'net::ERR_ABORTED';
      (delivered ? target.warnings : target.errors).push(delivered ? `${text} (after HTTP 200)` : text);
    }, () => target.errors.push(text));
  });
  page.on('response', (r) => { if (r.status() >= 400) sink.errors.push(`HTTP ${r.status()}: ${r.url()}`); });
  await page.goto(`${server.base}/render/page.html`);
  await page.waitForFunction(() => window.radbakeReady === true, null, { timeout: 30000 });
  if (sink.errors.length) throw new Error(`the harness page failed to load:\n  ${sink.errors.join('\n  ')}`);

  async function render(o) {
    const width = o.width ?? 256, height = o.height ?? 256;
    const folder = server.mount(path.dirname(path.resolve(o.file)));
    const url = folder + encodeURIComponent(path.basename(o.file));
    sink = { errors: [], warnings: [] };
    const { errors: consoleErrors, warnings: consoleWarnings } = sink;
    try {
      // page.evaluate has no time limit of its own: a loader that never settles would hang the caller.
      const timeoutMs = o.timeoutMs ?? 60000;
      let timer;
      const result = await Promise.race([
        page.evaluate((opts) => window.radbakeRender(opts), {
          url, mode: o.mode ?? 'stock', camera: o.camera, width, height, points: o.points || [],
          pluginOptions: o.pluginOptions, mipmaps: o.mipmaps, meshopt: !!o.meshopt, antialias: !!o.antialias,
          background: o.background,
        }),
        new Promise((_, reject) => { timer = setTimeout(() => reject(new Error(`render of ${o.file} took over ${timeoutMs} ms`)), timeoutMs); }),
      ]).finally(() => clearTimeout(timer));
      const image = { width, height, rgba: new Uint8Array(Buffer.from(result.rgba, 'base64')) };
      if (o.out) await writeFile(o.out, encodePng(width, height, image.rgba));
      const points = (o.points || []).map(([x, y], i) => ({
        x, y, rgb: pixelMean(image, x, y, o.patch ?? 0), hit: result.hits[i],
      }));
      return { image, points, consoleErrors, consoleWarnings, lights: result.lights, materials: result.materials,
        userData: result.userData, three: result.three, gl: result.gl, ms: result.ms, png: o.out ?? null };
    } catch (e) {
      e.message += consoleErrors.length ? `\npage console errors:\n  ${consoleErrors.join('\n  ')}` : '';
      throw e;
    }
  }

  return {
    render,
    async close() {
      await browser.close();
      await server.close();
    },
  };
}

function parseArgs(argv) {
  const o = { mode: 'stock', width: 256, height: 256, points: [], patch: 0 };
  let cameraSpec = null;
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(`${a} needs a value`);
      return argv[++i];
    };
    if (a === '--mode') o.mode = value();
    else if (a === '--camera') cameraSpec = value();
    else if (a === '--size') [o.width, o.height] = value().split('x').map(Number);
    else if (a === '--out') o.out = value();
    else if (a === '--points') o.points = value().split(';').filter(Boolean).map((p) => p.split(',').map(Number));
    else if (a === '--patch') o.patch = Number(value());
    else if (a === '--exposure') o.pluginOptions = { ...o.pluginOptions, exposure: Number(value()) };
    else if (a === '--mipmaps') o.mipmaps = value();
    else if (a === '--meshopt') o.meshopt = true;
    else if (a.startsWith('--')) throw new Error(`unknown option ${a}`);
    else if (o.file) throw new Error(`one file only (got ${o.file} and ${a})`);
    else o.file = a;
  }
  if (!o.file) throw new Error('usage: render.mjs FILE [--mode stock|plugin] [--camera X,Y,Z/TX,TY,TZ/FOV|gltf] [--size WxH] [--out PNG] [--points "X,Y;..."] [--patch R] [--exposure E] [--mipmaps as-written|force] [--meshopt]');
  if (![o.width, o.height].every((n) => Number.isInteger(n) && n > 0 && n <= 4096)) throw new Error('--size WxH, 1..4096');
  return { o, cameraSpec };
}

async function main() {
  const { o, cameraSpec } = parseArgs(process.argv.slice(2));
  if (!cameraSpec || cameraSpec === 'gltf') o.camera = await gltfCamera(o.file);
  else {
    const [p, t, fov] = cameraSpec.split('/');
    o.camera = { position: p.split(',').map(Number), target: t.split(',').map(Number), fov: Number(fov) };
  }
  const renderer = await openRenderer();
  try {
    const r = await renderer.render(o);
    console.log(JSON.stringify({ png: r.png, three: r.three, gl: r.gl, ms: r.ms, consoleErrors: r.consoleErrors,
      consoleWarnings: r.consoleWarnings, lights: r.lights, materials: r.materials,
      points: r.points.map((p) => ({ ...p, rgb: p.rgb.map((v) => Math.round(v * 100) / 100) })) }, null, 1));
    process.exitCode = r.consoleErrors.length ? 1 : 0;
  } finally {
    await renderer.close();
  }
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  main().catch((e) => {
    console.error(`render.mjs: ${e.message}`);
    process.exit(2);
  });
}

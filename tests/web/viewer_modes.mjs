// Drives `radbake view`'s page in headless Chromium for tests/cli/view_test.cpp and ./dev
// view-screenshots: opens URL at WIDTH x HEIGHT through the glTF's first camera, then runs the
// steps of a JSON list, each { mode, scale?, max?, compare?, split?, ev?, walk?, hold?: KEY (held
// for half a second), pixels: [[x, y], ...], sensors: [k, ...] (where sensor k is drawn, its
// reading and the pixel there), probes: [k, ...] (light probe k's sphere: where it is drawn, the
// pixel there with the probes hidden and shown), screenshot?: FILE, button?: true (the page's own
// screenshot button: the download's size), camera?: k (-1: the scene framed) }, and prints one
// JSON line: { consoleErrors, loadSeconds, firstFrameSeconds (navigation to the first frame
// drawn), firstCamera (where the page opened, before camera 0), evRange: [min, max, start],
// steps: [{ scale, camera, download, pixels: [{ x, y, rgb, pick }], probeCount, probes: [{ x, y,
// position, hidden, shown }] }] }.
//   node viewer_modes.mjs URL WIDTH HEIGHT 'STEPS'
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from '../../web/render/render.mjs';
import { WEB_DIR } from './support.mjs';

// playwright-core is web/'s package (web/package-lock.json), not this folder's.
const { chromium } = await import(pathToFileURL(path.join(WEB_DIR, 'node_modules', 'playwright-core', 'index.mjs')).href);

const [url, width, height, stepsJson] = process.argv.slice(2);
const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: CHROMIUM_ARGS, headless: true });
try {
  const context = await browser.newContext({ viewport: { width: Number(width), height: Number(height) }, deviceScaleFactor: 1, acceptDownloads: true });
  const page = await context.newPage();
  const consoleErrors = [];
  page.on('console', (msg) => { if (msg.type() === 'error') consoleErrors.push(msg.text()); });
  page.on('pageerror', (error) => consoleErrors.push(String(error)));
  await page.goto(url);
  await page.waitForFunction(() => window.radbakeView !== undefined);
  await page.evaluate(() => window.radbakeView.ready);
  await page.waitForFunction(() => window.radbakeView.firstFrameSeconds() !== undefined);
  const firstFrameSeconds = await page.evaluate(() => window.radbakeView.firstFrameSeconds());
  const firstCamera = await page.evaluate(() => window.radbakeView.cameraPosition());
  const evRange = await page.evaluate(() => window.radbakeView.evRange());
  await page.evaluate(() => window.radbakeView.useCamera(0));
  const steps = [];
  for (const step of JSON.parse(stepsJson)) {
    const scale = await page.evaluate((s) => window.radbakeView.setMode(s.mode, s), step);
    if (step.hold) {
      await page.keyboard.down(step.hold);
      await page.waitForTimeout(500);
      await page.keyboard.up(step.hold);
    }
    let download = null;
    if (step.button) {
      const [file] = await Promise.all([page.waitForEvent('download'), page.click('#screenshot')]);
      download = (await readFile(await file.path())).length;
    }
    const camera = await page.evaluate(() => window.radbakeView.cameraPosition());
    const sensors = [];
    for (const k of step.sensors || []) {
      const s = await page.evaluate((i) => window.radbakeView.sensor(i), k);
      const rgb = await page.evaluate(([px, py]) => window.radbakeView.pixel(px, py), [Math.floor(s.x), Math.floor(s.y)]);
      sensors.push({ ...s, rgb });
    }
    const probes = [];
    let probeCount = null;
    if (step.probes) {
      probeCount = await page.evaluate(() => window.radbakeView.showProbes(false));
      for (const k of step.probes) {
        const p = await page.evaluate((i) => window.radbakeView.probe(i), k);
        const at = [Math.floor(p.x), Math.floor(p.y)];
        const hidden = await page.evaluate(([px, py]) => window.radbakeView.pixel(px, py), at);
        await page.evaluate(() => window.radbakeView.showProbes(true));
        const shown = await page.evaluate(([px, py]) => window.radbakeView.pixel(px, py), at);
        await page.evaluate(() => window.radbakeView.showProbes(false));
        probes.push({ ...p, hidden, shown });
      }
    }
    const pixels = [];
    for (const [x, y] of step.pixels || []) {
      const rgb = await page.evaluate(([px, py]) => window.radbakeView.pixel(px, py), [x, y]);
      const pick = await page.evaluate(([px, py]) => window.radbakeView.pick(px + 0.5, py + 0.5), [x, y]);
      pixels.push({ x, y, rgb, pick });
    }
    if (step.screenshot) await page.screenshot({ path: step.screenshot });
    steps.push({ scale, camera, download, pixels, sensors, probeCount, probes });
  }
  const loadSeconds = await page.evaluate(() => window.radbakeView.loadSeconds());
  console.log(JSON.stringify({ consoleErrors, loadSeconds, firstFrameSeconds, firstCamera, evRange, steps }));
} finally {
  await browser.close();
}

// Drives `radbake view`'s page in headless Chromium for tests/cli/view_test.cpp: opens URL at
// 256 x 256, waits for the bake, takes the glTF's first camera and reads the pixels given as
// x,y pairs. Prints one JSON line: { consoleErrors: [...], picks: [{x, y, surface, page, texel,
// value, unit} | null, ...] }.
//   node viewer_pick.mjs URL x,y [x,y ...]
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from '../../web/render/render.mjs';
import { WEB_DIR } from './support.mjs';

// playwright-core is web/'s package (web/package-lock.json), not this folder's.
const { chromium } = await import(pathToFileURL(path.join(WEB_DIR, 'node_modules', 'playwright-core', 'index.mjs')).href);

const [url, ...pixels] = process.argv.slice(2);
const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: CHROMIUM_ARGS, headless: true });
try {
  const page = await browser.newPage({ viewport: { width: 256, height: 256 }, deviceScaleFactor: 1 });
  const consoleErrors = [];
  page.on('console', (msg) => { if (msg.type() === 'error') consoleErrors.push(msg.text()); });
  page.on('pageerror', (error) => consoleErrors.push(String(error)));
  await page.goto(url);
  await page.waitForFunction(() => window.radbakeView !== undefined);
  await page.evaluate(() => window.radbakeView.ready);
  await page.evaluate(() => window.radbakeView.useCamera(0));
  const picks = [];
  for (const p of pixels) {
    const [x, y] = p.split(',').map(Number);
    const pick = await page.evaluate(([px, py]) => window.radbakeView.pick(px, py), [x, y]);
    picks.push(pick && { x, y, ...pick });
  }
  console.log(JSON.stringify({ consoleErrors, picks }));
} finally {
  await browser.close();
}

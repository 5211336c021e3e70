// Builds docs/using_the_result_far_view.png from the far-view test's screenshots: the middle of
// the far view (the box small on screen), enlarged with nearest-neighbour pixels, as radbake writes
// the sampler (left: no mipmaps) and with mipmaps forced on (right), where neighbouring charts
// bleed into the blocks' faces.
// usage: node web/render/far_view_figure.mjs WORK/far_view OUT.png   (WORK: the ctest build's web_tests)
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { decodePng, encodePng } from './png.mjs';

const [dir, out] = process.argv.slice(2);
if (!dir || !out) throw new Error('usage: far_view_figure.mjs FAR_VIEW_WORK_DIR OUT.png');
// The box (about 24 pixels wide) sits left of and below the image centre: the camera aims at the short block.
const CROP = 32, SCALE = 8, GAP = 4, CENTRE = [124, 122];
const panels = ['far_front_display.png', 'far_front_display_mipmaps.png'].map((f) => decodePng(readFileSync(path.join(dir, f))));
const side = CROP * SCALE, width = panels.length * side + (panels.length - 1) * GAP;
const rgba = new Uint8Array(width * side * 4).fill(255);
panels.forEach((img, k) => {
  const x0 = CENTRE[0] - CROP / 2, y0 = CENTRE[1] - CROP / 2;
  for (let y = 0; y < side; y++) {
    for (let x = 0; x < side; x++) {
      const s = ((y0 + Math.floor(y / SCALE)) * img.width + x0 + Math.floor(x / SCALE)) * 4;
      const d = (y * width + k * (side + GAP) + x) * 4;
      rgba.set(img.rgba.subarray(s, s + 4), d);
    }
  }
});
writeFileSync(out, encodePng(width, side, rgba));

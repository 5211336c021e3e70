// The viewer's colour scales and their legends: Google's turbo map (Mikhailov 2019, by its
// published polynomial, as io/analysis/false_colour.cpp draws radbake's own images) and radbake diff's
// white-to-red/blue difference.

const RED = [0.13572138, 4.61539260, -42.66032258, 132.13108234, -152.94239396, 59.28637943];
const GREEN = [0.09140261, 2.19418839, 4.84296658, -14.18503333, 4.27729857, 2.82956604];
const BLUE = [0.10667330, 12.64194608, -60.58204836, 110.36276771, -89.90310912, 27.34824973];

const horner = (c, x) => c.reduceRight((sum, k) => sum * x + k, 0);

/** turbo at fraction x (0..1), as sRGB bytes. */
export function turbo(x) {
  const t = Math.min(1, Math.max(0, Number.isNaN(x) ? 0 : x));
  return [RED, GREEN, BLUE].map((c) => Math.round(Math.min(1, Math.max(0, horner(c, t))) * 255));
}

const glslPolynomial = (c) => c.map((k) => k.toFixed(8)).reduceRight((rest, k, i) => (i === c.length - 1 ? k : `${k} + x * (${rest})`));

/** The same map in GLSL: vec3 turbo(float x), sRGB-encoded, x clamped to 0..1 by the caller. */
export const turboGlsl = `
  vec3 turbo(float x) {
    return clamp(vec3(${glslPolynomial(RED)}, ${glslPolynomial(GREEN)}, ${glslPolynomial(BLUE)}), 0.0, 1.0);
  }`;

/** The smallest of 1, 2, 2.5, 5 x 10^k at or above v. */
export function niceNumberAtOrAbove(v) {
  if (!(v > 0)) return 1;
  const decade = Math.pow(10, Math.floor(Math.log10(v)));
  for (const m of [1, 2, 2.5, 5, 10]) if (m * decade >= v * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

function label(v) {
  if (v >= 10000) return `${+(v / 1000).toPrecision(3)}k`;
  return `${+v.toPrecision(3)}`;
}

/**
 * Draws a vertical legend into a canvas. spec: { kind: 'turbo', max, logarithmic, decades, unit }
 * or { kind: 'difference', scale } (scale: the relative difference at full colour).
 */
export function drawLegend(canvas, spec) {
  const g = canvas.getContext('2d');
  const w = canvas.width, h = canvas.height, bar = { x: 8, y: 24, w: 18, h: h - 40 };
  g.fillStyle = 'rgba(0, 0, 0, 0.6)';
  g.fillRect(0, 0, w, h);
  for (let row = 0; row < bar.h; row++) {
    const f = 1 - row / (bar.h - 1);
    let rgb;
    if (spec.kind === 'turbo') rgb = turbo(f);
    else {
      const s = 2 * f - 1, k = Math.round(255 * (1 - Math.abs(s)));
      rgb = s > 0 ? [255, k, k] : [k, k, 255];
    }
    g.fillStyle = `rgb(${rgb.join(',')})`;
    g.fillRect(bar.x, bar.y + row, bar.w, 1);
  }
  g.fillStyle = '#eee';
  g.font = '12px sans-serif';
  const ticks = [];
  if (spec.kind === 'turbo' && spec.logarithmic) {
    for (let d = 0; d <= spec.decades; d++) ticks.push([d / spec.decades, label(spec.max / Math.pow(10, spec.decades - d))]);
    g.fillText(spec.unit, bar.x, 14);
  } else if (spec.kind === 'turbo') {
    for (let k = 0; k <= 4; k++) ticks.push([k / 4, label((spec.max * k) / 4)]);
    g.fillText(spec.unit, bar.x, 14);
  } else {
    for (const s of [-1, -0.5, 0, 0.5, 1]) ticks.push([(s + 1) / 2, `${s > 0 ? '+' : ''}${+(100 * s * spec.scale).toPrecision(3)}%`]);
    g.fillText('B − A', bar.x, 14);
  }
  for (const [f, text] of ticks) {
    const y = bar.y + (1 - f) * (bar.h - 1);
    g.fillRect(bar.x + bar.w, y, 4, 1);
    g.fillText(text, bar.x + bar.w + 6, y + 4);
  }
}

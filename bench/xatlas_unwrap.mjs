// xatlas (jpcy/xatlas, as the WebAssembly build watlas pinned in web/package-lock.json) unwraps a
// scene for bench/uv_compare, at the density that just fills one page:
//   node bench/xatlas_unwrap.mjs IN.gltf|glb OUT.glb PAGE PADDING
// Every primitive instance goes to xatlas in world space (as radbake sees the scene), so instanced
// meshes get charts of their own and texel sizes agree across nodes. xatlas's default chart options;
// pack options padding PADDING, resolution PAGE, and texelsPerUnit raised by bisection to the
// highest value for which everything lands in one atlas. OUT holds one mesh per instance, world
// positions and xatlas's UVs over the PAGE-texel page as TEXCOORD_0, for
// `radbake uv OUT --evaluate-texcoord 0`. Prints one JSON line: { seconds, texelsPerUnit, charts }.
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const WEB = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', 'web', 'node_modules');
const load = (module, file) => import(pathToFileURL(path.join(WEB, module, file)).href);
const { Document, NodeIO } = await load('@gltf-transform/core', 'dist/index.js');
const watlas = await load('watlas', 'dist/watlas.js');

const [input, output, pageArg, paddingArg] = process.argv.slice(2);
const page = Number(pageArg), padding = Number(paddingArg);
if (!output || !(page > 0) || !(padding >= 0)) {
  console.error('usage: node bench/xatlas_unwrap.mjs IN.gltf OUT.glb PAGE PADDING');
  process.exit(2);
}

const source = await new NodeIO().read(input);
const instances = [];  // { positions: Float32Array (world), indices: Uint32Array }
for (const scene of source.getRoot().listScenes())
  scene.traverse((node) => {
    const mesh = node.getMesh();
    if (!mesh) return;
    const m = node.getWorldMatrix();
    for (const prim of mesh.listPrimitives()) {
      if (prim.getMode() !== 4) continue;  // triangles only, as radbake bakes
      const position = prim.getAttribute('POSITION');
      const count = position.getCount();
      const world = new Float32Array(3 * count);
      const p = [0, 0, 0];
      for (let v = 0; v < count; ++v) {
        position.getElement(v, p);
        for (let r = 0; r < 3; ++r) world[3 * v + r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
      }
      const idx = prim.getIndices();
      const indices = idx ? Uint32Array.from(idx.getArray()) : Uint32Array.from({ length: count }, (_, i) => i);
      instances.push({ positions: world, indices });
    }
  });

await watlas.Initialize();
const start = performance.now();
const atlas = new watlas.Atlas();
for (const { positions, indices } of instances)
  atlas.addMesh({
    vertexPositionData: positions, vertexCount: positions.length / 3, vertexPositionStride: 12,
    indexData: indices, indexCount: indices.length,
  });
atlas.computeCharts({});
const pack = (texelsPerUnit) => {
  atlas.packCharts({ padding, resolution: page, texelsPerUnit });
  return atlas.atlasCount === 1 && atlas.width <= page && atlas.height <= page;
};
// xatlas's own estimate for this resolution starts the bracket.
pack(0);
let lo = 0, hi = 0;
const first = atlas.texelsPerUnit;
(pack(first) ? (lo = first) : (hi = first));
for (let step = 0; step < 40 && (lo === 0 || hi === 0); ++step) {
  const t = lo === 0 ? hi * 0.8 : lo * 1.25;
  (pack(t) ? (lo = t) : (hi = t));
}
for (let step = 0; step < 12; ++step) {
  const t = 0.5 * (lo + hi);
  (pack(t) ? (lo = t) : (hi = t));
}
if (!pack(lo)) throw new Error('xatlas: no density fits one page');
const seconds = (performance.now() - start) / 1000;

const out = new Document();
const buffer = out.createBuffer();
const material = out.createMaterial('grey');
const scene = out.createScene();
for (let i = 0; i < atlas.meshCount; ++i) {
  const am = atlas.getMesh(i);
  const n = am.vertexCount;
  const positions = new Float32Array(3 * n), uvs = new Float32Array(2 * n);
  const world = instances[i].positions;
  for (let v = 0; v < n; ++v) {
    const vertex = am.getVertex(v);
    positions.set(world.subarray(3 * vertex.xref, 3 * vertex.xref + 3), 3 * v);
    uvs[2 * v] = vertex.uv[0] / page;
    uvs[2 * v + 1] = vertex.uv[1] / page;
  }
  const indices = new Uint32Array(am.indexCount);
  am.getIndexArray(indices);
  const prim = out.createPrimitive()
    .setAttribute('POSITION', out.createAccessor().setType('VEC3').setArray(positions).setBuffer(buffer))
    .setAttribute('TEXCOORD_0', out.createAccessor().setType('VEC2').setArray(uvs).setBuffer(buffer))
    .setIndices(out.createAccessor().setType('SCALAR').setArray(indices).setBuffer(buffer))
    .setMaterial(material);
  scene.addChild(out.createNode(`instance_${i}`).setMesh(out.createMesh(`instance_${i}`).addPrimitive(prim)));
}
await new NodeIO().write(output, out);
console.log(JSON.stringify({ seconds, texelsPerUnit: lo, charts: atlas.chartCount }));
atlas.delete();

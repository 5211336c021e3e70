// Validates a .gltf/.glb with the Khronos glTF-Validator (npm package gltf-validator, which has no
// command-line entry of its own). Prints the report summary as JSON and exits 1 on any error.
// usage: node validate_gltf.mjs FILE
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate_gltf.mjs FILE');
  process.exit(2);
}
const bytes = new Uint8Array(await readFile(file));
const report = await validator.validateBytes(bytes, {
  uri: path.basename(file),
  maxIssues: 100,
  externalResourceFunction: (uri) =>
    readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
});
const issues = report.issues;
const errors = issues.messages.filter((m) => m.severity === 0);
console.log(JSON.stringify({
  file,
  errors: issues.numErrors,
  warnings: issues.numWarnings,
  infos: issues.numInfos,
  messages: issues.messages.filter((m) => m.severity <= 1).map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`),
}, null, 1));
process.exit(errors.length > 0 || issues.numErrors > 0 ? 1 : 0);

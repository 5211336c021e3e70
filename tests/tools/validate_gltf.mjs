// Validates .gltf/.glb files with the Khronos glTF-Validator (npm package gltf-validator, which has
// no command-line entry of its own). Prints one line of JSON per file, the report's summary, and
// exits 1 when any file has an error. Several files per run, so a corpus pays for Node's start-up once.
// usage: node validate_gltf.mjs FILE...
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node validate_gltf.mjs FILE...');
  process.exit(2);
}
let failed = false;
for (const file of files) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) =>
      readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const issues = report.issues;
  failed ||= issues.numErrors > 0;
  console.log(JSON.stringify({
    file,
    errors: issues.numErrors,
    warnings: issues.numWarnings,
    infos: issues.numInfos,
    messages: issues.messages.filter((m) => m.severity <= 1).map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`),
    info_codes: issues.messages.filter((m) => m.severity === 2).map((m) => `${m.code} ${m.pointer ?? ''}`),
  }));
}
process.exit(failed ? 1 : 0);

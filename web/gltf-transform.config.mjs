// gltf-transform --config PATH/gltf-transform.config.mjs ...: the stock extensions plus
// MOZ_lightmap, so `copy`, `optimize` and the other commands keep radbake's lightmaps
// (gltf-transform/moz-lightmap.mjs). PATH is web/ in the source tree, share/radbake/web/ installed.
//
// The extension must be built on the very @gltf-transform/core the running CLI uses: a second copy
// (one beside this file) has classes the CLI's reader does not know, and it then drops every
// texture coordinate set with no warning. So the packages are taken from beside the CLI that
// loads this file (process.argv[1]), wherever npm put it; loaded some other way, from here.
import { existsSync, readFileSync, realpathSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { mozLightmapExtension } from './gltf-transform/moz-lightmap.mjs';

// The ES module entry of a package's "exports" under Node's import conditions, in their order.
function importTarget(exports) {
  if (typeof exports === 'string') return exports;
  if (!exports || typeof exports !== 'object') return null;
  if ('.' in exports) return importTarget(exports['.']);
  for (const [condition, target] of Object.entries(exports))
    if (['node', 'import', 'default'].includes(condition)) {
      const found = importTarget(target);
      if (found) return found;
    }
  return null;
}

async function fromTheCli(name) {
  let cli;
  try {
    cli = realpathSync(process.argv[1]);
  } catch {
    return import(name);
  }
  let folder;
  try {
    folder = path.dirname(createRequire(cli).resolve(name));
  } catch {
    return import(name);
  }
  for (; ; folder = path.dirname(folder)) {
    const manifest = path.join(folder, 'package.json');
    if (existsSync(manifest)) {
      const json = JSON.parse(readFileSync(manifest, 'utf8'));
      if (json.name === name) return import(pathToFileURL(path.join(folder, importTarget(json.exports) ?? json.module ?? json.main)).href);
    }
    if (path.dirname(folder) === folder) return import(name);
  }
}

const core = await fromTheCli('@gltf-transform/core');
const { ALL_EXTENSIONS } = await fromTheCli('@gltf-transform/extensions');

export default { extensions: [...ALL_EXTENSIONS, mozLightmapExtension(core)] };

// gltf-transform --config web/gltf-transform.config.mjs ...: the stock extensions plus MOZ_lightmap,
// so `copy`, `optimize` and the other commands keep radbake's lightmaps (web/gltf-transform/).
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { MozLightmap } from './gltf-transform/moz-lightmap.mjs';

export default { extensions: [...ALL_EXTENSIONS, MozLightmap] };

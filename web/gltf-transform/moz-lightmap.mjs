// MOZ_lightmap for glTF Transform: without it, gltf-transform reads the extension as unknown and
// drops it (and then the lightmap texture and TEXCOORD_1 with it). Registered by
// web/gltf-transform.config.mjs, which passes the CLI's own @gltf-transform/core:
//   gltf-transform optimize --config web/gltf-transform.config.mjs IN.gltf OUT.glb
// Material extension {index, texCoord, intensity} (MOZ_lightmap's texture reference is the
// extension object itself, a textureInfo plus `intensity`); the page is an sRGB colour texture.
export const MOZ_LIGHTMAP = 'MOZ_lightmap';

// The extension's classes on `core`, a loaded @gltf-transform/core.
export function mozLightmapExtension(core) {
  const { Extension, ExtensionProperty, PropertyType, TextureChannel, TextureInfo } = core;
  const { R, G, B } = TextureChannel;

  class Lightmap extends ExtensionProperty {
    static EXTENSION_NAME = MOZ_LIGHTMAP;

    init() {
      this.extensionName = MOZ_LIGHTMAP;
      this.propertyType = 'Lightmap';
      this.parentTypes = [PropertyType.MATERIAL];
    }

    getDefaults() {
      return Object.assign(super.getDefaults(), {
        intensity: 1,
        lightmapTexture: null,
        lightmapTextureInfo: new TextureInfo(this.graph, 'lightmapTextureInfo'),
      });
    }

    getIntensity() { return this.get('intensity'); }
    setIntensity(intensity) { return this.set('intensity', intensity); }
    getLightmapTexture() { return this.getRef('lightmapTexture'); }
    getLightmapTextureInfo() { return this.getRef('lightmapTexture') ? this.getRef('lightmapTextureInfo') : null; }
    setLightmapTexture(texture) { return this.setRef('lightmapTexture', texture, { channels: R | G | B, isColor: true }); }
  }

  class MozLightmap extends Extension {
    static EXTENSION_NAME = MOZ_LIGHTMAP;
    extensionName = MOZ_LIGHTMAP;
    prereadTypes = [PropertyType.MESH];
    prewriteTypes = [PropertyType.MESH];

    createLightmap() {
      return new Lightmap(this.document.getGraph());
    }

    read() { return this; }
    write() { return this; }

    preread(context) {
      const json = context.jsonDoc.json;
      const textureDefs = json.textures || [];
      (json.materials || []).forEach((materialDef, materialIndex) => {
        const def = materialDef.extensions && materialDef.extensions[MOZ_LIGHTMAP];
        if (!def) return;
        const lightmap = this.createLightmap();
        context.materials[materialIndex].setExtension(MOZ_LIGHTMAP, lightmap);
        if (def.extras) lightmap.setExtras(def.extras);
        if (def.intensity !== undefined) lightmap.setIntensity(def.intensity);
        if (def.index !== undefined && textureDefs[def.index] && textureDefs[def.index].source !== undefined) {
          lightmap.setLightmapTexture(context.textures[textureDefs[def.index].source]);
          context.setTextureInfo(lightmap.getLightmapTextureInfo(), def);
        }
      });
      return this;
    }

    prewrite(context) {
      const json = context.jsonDoc.json;
      for (const material of this.document.getRoot().listMaterials()) {
        const lightmap = material.getExtension(MOZ_LIGHTMAP);
        if (!lightmap) continue;
        const materialDef = json.materials[context.materialIndexMap.get(material)];
        const def = context.createPropertyDef(lightmap);
        const texture = lightmap.getLightmapTexture();
        if (texture) Object.assign(def, context.createTextureInfoDef(texture, lightmap.getLightmapTextureInfo()));
        def.intensity = lightmap.getIntensity();
        materialDef.extensions = materialDef.extensions || {};
        materialDef.extensions[MOZ_LIGHTMAP] = def;
      }
      return this;
    }
  }

  return MozLightmap;
}

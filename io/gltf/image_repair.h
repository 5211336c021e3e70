// Internal to io/: the input's images as the engine file may carry them. glTF's images are PNG or
// JPEG, or WebP where a texture names them through EXT_texture_webp, and the Khronos glTF-Validator
// reads their bytes (IMAGE_DATA_INVALID, IMAGE_UNRECOGNIZED_FORMAT, IMAGE_MIME_TYPE_INVALID,
// TEXTURE_INVALID_IMAGE_MIME_TYPE). What it would reject is not written (docs/hostile_input.md).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/gltf/gltf_source.h"

namespace radbake {

// Why the engine file cannot carry image `i` of `source`; empty when it can: a PNG or JPEG that
// decodes, or WebP that a texture names through EXT_texture_webp. The loader warns with it,
// naming the image's pointer, and the writer leaves such images out.
std::string unwritable_image(const GltfSource& source, size_t i);

// Makes the images of `doc` (the checked document of `source`) what the engine file may carry:
// mimeTypes (and data URIs' media types) as the bytes say; texture extensions naming an image not
// written, or EXT_texture_webp naming one that is no WebP, dropped with a warning (a PNG or JPEG
// it named becomes the texture's source where it has none); textures' sources of images not written
// removed, and the material references to textures left with no image. Returns, per image,
// whether it is written; the writer removes the others (remove_objects) once it has copied the rest.
// PNGs in data URIs are made plain (make_png_plain, below) here; the writer does those in files and
// buffer views as it copies them.
std::vector<uint8_t> repair_images(nlohmann::ordered_json& doc, const GltfSource& source, std::vector<std::string>& warnings);

// Takes out of a PNG the chunks glTF viewers ignore and the validator flags as unsupported features
// (IMAGE_FEATURES_UNSUPPORTED): colour-space information other than sRGB's (cHRM, gAMA and iCCP,
// as glTF's colour textures are sRGB and its others linear whatever they say), non-square pixels
// (pHYs) and animation (acTL, fcTL, fdAT: the default image stays). Chunks are whole, with their
// own CRCs, so the rest is unchanged. Returns a warning naming `pointer` and the chunks, or ""
// when nothing was taken out or the bytes are no PNG.
std::string make_png_plain(std::string& bytes, const std::string& pointer);

}  // namespace radbake

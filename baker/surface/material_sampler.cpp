#include "baker/surface/material_sampler.h"

#include <algorithm>
#include <cmath>

namespace radbake {
namespace {

// Reflectance is an average over each lightmap texel's footprint, so texture detail finer than
// this never changes a bake; capping the finest level bounds the memory a 8k texture costs.
constexpr int kMaxSampledSize = 1024;

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// A texel coordinate far outside the texture (a UV of 1e6, a texture transform scale of 1e19) would
// overflow the int it is floored to. Any whole number of mirror periods (two texture widths) away
// every wrap mode reads the same texel, and fmod is exact, so only the fraction that matters is kept.
float within_int_range(float f, int n, Wrap mode) {
  if (mode == Wrap::ClampToEdge) return std::clamp(f, -1.0f, float(n));
  const double period = 2.0 * n;
  double r = std::fmod(double(f), period);
  return float(r < 0 ? r + period : r);
}

int wrap_index(int i, int n, Wrap mode) {
  switch (mode) {
    case Wrap::ClampToEdge:
      return std::clamp(i, 0, n - 1);
    case Wrap::MirroredRepeat: {
      int period = 2 * n;
      int m = ((i % period) + period) % period;
      return m < n ? m : period - 1 - m;
    }
    case Wrap::Repeat:
    default:
      return ((i % n) + n) % n;
  }
}

Vec2 apply_transform(const TextureTransform& t, Vec2 uv) {
  Vec2 s{uv.x * t.scale.x, uv.y * t.scale.y};
  float c = std::cos(t.rotation), r = std::sin(t.rotation);
  // KHR_texture_transform: translation * rotation * scale, rotation = mat3(cos, sin, 0, -sin, cos, 0, ...)
  return {c * s.x - r * s.y + t.offset.x, r * s.x + c * s.y + t.offset.y};
}

}  // namespace

MaterialSampler::MaterialSampler(const Scene& scene, const Surface& surface, float emission_scale,
                                 const Glazing& glazing)
    : scene_(scene), surface_(surface), emission_scale_(emission_scale) {
  for (const Material& m : scene.materials) {
    // A clear pane of the material's index when nothing says what it passes: its two faces'
    // reflections alone, (1 - r0) / (1 + r0).
    const float along_normal = m.visible_transmittance >= 0 ? m.visible_transmittance
                               : glazing.transmittance >= 0 ? glazing.transmittance
                                                            : PaneCurve(GlazingModel::Fresnel, m.ior, 1).clear_faces();
    pane_transmittance_.push_back(m.transmission * along_normal);
    pane_curve_.push_back(PaneCurve(glazing.model, m.ior, along_normal));
    alpha_texture_.push_back(m.alpha_mode != AlphaMode::Opaque && m.base_color_texture.present()
                                 ? texture_for(m.base_color_texture.image, Decode::Alpha)
                                 : -1);
    base_texture_.push_back(m.base_color_texture.present() ? texture_for(m.base_color_texture.image, Decode::Srgb) : -1);
    metallic_texture_.push_back(
        m.metallic_roughness_texture.present() ? texture_for(m.metallic_roughness_texture.image, Decode::Linear) : -1);
    emissive_texture_.push_back(m.emissive_texture.present() ? texture_for(m.emissive_texture.image, Decode::Srgb) : -1);
    normal_texture_.push_back(m.normal_texture.present() ? texture_for(m.normal_texture.image, Decode::Linear) : -1);
  }
}

Vec3 MaterialSampler::mapped_normal(uint32_t triangle, Vec2 bary, float spacing) const {
  const Vec3 n = surface_.shading_normal(triangle, bary);
  const int mi = surface_.material[triangle];
  if (mi < 0 || normal_texture_[size_t(mi)] < 0) return n;
  const Material& m = scene_.materials[size_t(mi)];
  const MeshInstance& inst = scene_.instances[surface_.instance[triangle]];
  if (size_t(m.normal_texture.tex_coord) >= inst.texcoords.size() || inst.texcoords[size_t(m.normal_texture.tex_coord)].empty())
    return n;
  // Tangent along +u, bitangent against +v (glTF's image rows run down while its normal maps'
  // +Y points up), from the triangle's positions and texture coordinates.
  const std::vector<Vec2>& set = inst.texcoords[size_t(m.normal_texture.tex_coord)];
  Vec2 uv[3];
  for (int k = 0; k < 3; ++k) uv[k] = apply_transform(m.normal_texture.transform, set[surface_.corner_vertex[3 * triangle + k]]);
  const Vec3* p = &surface_.corners[3 * triangle];
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const Vec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
  const float det = cross2(d1, d2);
  if (!(std::fabs(det) > 1e-20f)) return n;
  Vec3 tangent = (e1 * d2.y - e2 * d1.y) / det, bitangent = (e2 * d1.x - e1 * d2.x) / det * -1.0f;
  tangent = normalize(tangent - n * dot(n, tangent));
  bitangent = normalize(bitangent - n * dot(n, bitangent) - tangent * dot(tangent, bitangent));
  if (length(tangent) == 0 || length(bitangent) == 0) return n;
  const Vec3 t = sample(m.normal_texture, normal_texture_[size_t(mi)], triangle, bary, spacing) * 2.0f - Vec3{1, 1, 1};
  const Vec3 mapped = normalize(tangent * (t.x * m.normal_scale) + bitangent * (t.y * m.normal_scale) + n * t.z);
  return length(mapped) > 0 ? mapped : n;
}

int MaterialSampler::texture_for(int image_index, Decode decode) {
  auto known = texture_of_image_.find({image_index, decode});
  if (known != texture_of_image_.end()) return known->second;
  const Image& image = scene_.images[size_t(image_index)];
  Texture tex;
  // Finest level: the image box-filtered by a whole factor until it fits kMaxSampledSize.
  int factor = std::max(1, std::max((image.width + kMaxSampledSize - 1) / kMaxSampledSize,
                                    (image.height + kMaxSampledSize - 1) / kMaxSampledSize));
  Level top{std::max(1, image.width / factor), std::max(1, image.height / factor), {}};
  top.texels.assign(size_t(top.width) * top.height, Vec3{});
  for (int y = 0; y < top.height; ++y)
    for (int x = 0; x < top.width; ++x) {
      Vec3 acc{};
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          int sx = std::min(image.width - 1, x * factor + dx), sy = std::min(image.height - 1, y * factor + dy);
          for (int c = 0; c < 3; ++c) {
            float v = image.channel(sx, sy, decode == Decode::Alpha ? 3 : c);
            acc[c] += decode == Decode::Srgb ? srgb_to_linear(v) : v;
          }
        }
      top.texels[size_t(y) * top.width + x] = acc / float(factor * factor);
    }
  tex.levels.push_back(std::move(top));
  while (tex.levels.back().width > 1 || tex.levels.back().height > 1) {
    const Level& fine = tex.levels.back();
    Level coarse{std::max(1, fine.width / 2), std::max(1, fine.height / 2), {}};
    coarse.texels.resize(size_t(coarse.width) * coarse.height);
    for (int y = 0; y < coarse.height; ++y)
      for (int x = 0; x < coarse.width; ++x) {
        Vec3 acc{};
        for (int k = 0; k < 4; ++k) {
          int sx = std::min(fine.width - 1, 2 * x + (k & 1)), sy = std::min(fine.height - 1, 2 * y + (k >> 1));
          acc += fine.texels[size_t(sy) * fine.width + sx];
        }
        coarse.texels[size_t(y) * coarse.width + x] = acc * 0.25f;
      }
    tex.levels.push_back(std::move(coarse));
  }
  textures_.push_back(std::move(tex));
  return texture_of_image_[{image_index, decode}] = int(textures_.size() - 1);
}

Vec3 MaterialSampler::sample(const TextureRef& ref, int texture, uint32_t triangle, Vec2 bary, float spacing) const {
  const MeshInstance& inst = scene_.instances[surface_.instance[triangle]];
  if (size_t(ref.tex_coord) >= inst.texcoords.size() || inst.texcoords[size_t(ref.tex_coord)].empty())
    return {1, 1, 1};  // io/ reports the missing set; a neutral texel keeps the factor's colour
  const std::vector<Vec2>& set = inst.texcoords[size_t(ref.tex_coord)];
  Vec2 uv[3];
  for (int k = 0; k < 3; ++k) uv[k] = apply_transform(ref.transform, set[surface_.corner_vertex[3 * triangle + k]]);
  Vec2 p = uv[0] * (1 - bary.x - bary.y) + uv[1] * bary.x + uv[2] * bary.y;

  const Texture& tex = textures_[size_t(texture)];
  const Level& finest = tex.levels.front();
  // Texture texels per lightmap texel, from the two parameterisations' area ratio.
  const Vec2* lm = &surface_.corner_lightmap[3 * triangle];
  float lm_area = std::fabs(cross2(lm[1] - lm[0], lm[2] - lm[0]));
  float uv_area = std::fabs(cross2(uv[1] - uv[0], uv[2] - uv[0])) * float(finest.width) * float(finest.height);
  float footprint = lm_area > 0 ? spacing * std::sqrt(uv_area / lm_area) : 1.0f;
  int level = footprint > 1 ? std::min(int(tex.levels.size()) - 1, int(std::log2(footprint))) : 0;
  const Level& L = tex.levels[size_t(level)];

  float fx = p.x * L.width - 0.5f, fy = p.y * L.height - 0.5f;
  if (!std::isfinite(fx) || !std::isfinite(fy)) return {1, 1, 1};
  fx = within_int_range(fx, L.width, ref.wrap_s);
  fy = within_int_range(fy, L.height, ref.wrap_t);
  int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  float tx = fx - x0, ty = fy - y0;
  auto at = [&](int x, int y) {
    return L.texels[size_t(wrap_index(y, L.height, ref.wrap_t)) * L.width + size_t(wrap_index(x, L.width, ref.wrap_s))];
  };
  return (at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx) * (1 - ty) + (at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx) * ty;
}

Rgb MaterialSampler::reflectance(uint32_t triangle, Vec2 bary, float spacing) const {
  int mi = surface_.material[triangle];
  const Material& m = material_of(scene_, mi);
  Rgb albedo = m.base_color;
  float metallic = m.metallic;
  if (mi >= 0 && base_texture_[size_t(mi)] >= 0)
    albedo = albedo * sample(m.base_color_texture, base_texture_[size_t(mi)], triangle, bary, spacing);
  if (mi >= 0 && metallic_texture_[size_t(mi)] >= 0)
    metallic *= sample(m.metallic_roughness_texture, metallic_texture_[size_t(mi)], triangle, bary, spacing).z;
  const MeshInstance& inst = scene_.instances[surface_.instance[triangle]];
  if (!inst.colors.empty()) {
    const uint32_t* v = &surface_.corner_vertex[3 * triangle];
    albedo = albedo * (inst.colors[v[0]] * (1 - bary.x - bary.y) + inst.colors[v[1]] * bary.x + inst.colors[v[2]] * bary.y);
  }
  // Diffuse only where the surface is there and does not let the light through (glTF's
  // transmission takes its share from the diffuse lobe).
  const float diffuse = coverage(triangle, bary, spacing) * (1 - m.transmission);
  Rgb rho = albedo * (std::clamp(1.0f - metallic, 0.0f, 1.0f) * diffuse);
  for (int c = 0; c < 3; ++c) rho[c] = std::clamp(std::isfinite(rho[c]) ? rho[c] : 0.0f, 0.0f, kMaxReflectance);
  return rho;
}

Rgb MaterialSampler::emission_bound(uint32_t triangle) const {
  const Material& m = material_of(scene_, surface_.material[triangle]);
  if (!m.emits()) return {0, 0, 0};
  return m.emissive * (m.emissive_strength * emission_scale_ * kExitancePerEmissiveUnit);
}

Rgb MaterialSampler::emission(uint32_t triangle, Vec2 bary, float spacing) const {
  int mi = surface_.material[triangle];
  Rgb e = emission_bound(triangle);
  if (max_component(e) <= 0) return e;
  const Material& m = material_of(scene_, mi);
  if (mi >= 0 && emissive_texture_[size_t(mi)] >= 0)
    e = e * sample(m.emissive_texture, emissive_texture_[size_t(mi)], triangle, bary, spacing);
  return e;
}

float MaterialSampler::coverage(uint32_t triangle, Vec2 bary, float spacing) const {
  const int mi = surface_.material[triangle];
  const Material& m = material_of(scene_, mi);
  if (m.alpha_mode == AlphaMode::Opaque) return 1;
  float alpha = m.base_alpha;
  if (alpha_texture_[size_t(mi)] >= 0)
    alpha *= sample(m.base_color_texture, alpha_texture_[size_t(mi)], triangle, bary, spacing).x;
  if (m.alpha_mode == AlphaMode::Mask) return alpha >= m.alpha_cutoff ? 1.0f : 0.0f;
  return std::clamp(std::isfinite(alpha) ? alpha : 1.0f, 0.0f, 1.0f);
}

float MaterialSampler::transmittance(uint32_t triangle, Vec2 bary, Vec3 direction) const {
  const int mi = surface_.material[triangle];
  if (mi < 0) return 0;
  const float present = coverage(triangle, bary, 0);
  float pane = pane_transmittance_[size_t(mi)];
  if (pane > 0) {
    // The glazing's visible transmittance is along the normal; away from it, less (glazing.h).
    const float c = std::fabs(dot(direction, surface_.normal[triangle])) / length(direction);
    pane *= pane_curve_[size_t(mi)].relative(c);
  }
  return (1 - present) + present * pane;
}

float MaterialSampler::diffuse_transmittance(uint32_t triangle, Vec2 bary) const {
  const int mi = surface_.material[triangle];
  if (mi < 0) return 0;
  const float present = coverage(triangle, bary, 0);
  return (1 - present) + present * pane_transmittance_[size_t(mi)] * pane_curve_[size_t(mi)].diffuse_ratio();
}

bool MaterialSampler::see_through(uint32_t triangle) const {
  const int mi = surface_.material[triangle];
  return mi >= 0 && (scene_.materials[size_t(mi)].alpha_mode != AlphaMode::Opaque || pane_transmittance_[size_t(mi)] > 0);
}

bool MaterialSampler::glazing(uint32_t triangle) const {
  const int mi = surface_.material[triangle];
  return mi >= 0 && pane_transmittance_[size_t(mi)] > 0;
}

bool MaterialSampler::is_uniform(uint32_t triangle) const {
  int mi = surface_.material[triangle];
  if (!scene_.instances[surface_.instance[triangle]].colors.empty()) return false;
  return mi < 0 || (base_texture_[size_t(mi)] < 0 && metallic_texture_[size_t(mi)] < 0 && emissive_texture_[size_t(mi)] < 0 &&
                    alpha_texture_[size_t(mi)] < 0);
}

bool MaterialSampler::emits(uint32_t triangle) const { return material_of(scene_, surface_.material[triangle]).emits(); }

}  // namespace radbake

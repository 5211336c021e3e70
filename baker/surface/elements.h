// Elements are the lightmap texels the surface covers: the receivers of the radiosity solution,
// each with a sample point on the surface, a normal, its share of surface area and its material.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "baker/surface/material_sampler.h"
#include "baker/surface/surface.h"
#include "base/math.h"
#include "base/progress.h"

namespace radbake {

class RayTracer;

enum ElementFlags : uint8_t {
  kPushedOut = 1,     // the texel centre was behind nearby geometry; the sample moved in front of it
  kNearGeometry = 2,  // other geometry crosses or covers part of the footprint: rays start only from
                      // the part on the sample's side (visible_cells)
  kBuried = 4,        // the sample sees mostly back faces: it is inside geometry, valued by dilation
  kJoinsRight = 8,    // the element to the right (same chart) is on the same side of all geometry
  kJoinsDown = 16,    // likewise the element below; patches only grow across these joins
  kFiltered = 32,     // reflectance and emission are box-filtered over the footprint (else read once)
  kFlatTexel = 64,    // one plane of one chart covers the whole texel, whichever triangles it is cut into
  kUnderCover = 128,  // under_cover at the sample: the texel is in a thin gap (under a lamp hung just
                      // under a ceiling), not in the open beside it
};

struct Elements {
  // One entry per element, in page, row, column order.
  std::vector<Vec3> position;     // sample point on the surface, world space
  std::vector<Vec3> normal;       // unit shading normal at the sample
  std::vector<float> area;        // m^2 of surface inside the texel
  std::vector<Rgb> reflectance;   // diffuse, averaged over the texel's footprint
  std::vector<Rgb> emission;      // exitance, lm/m2, averaged over the footprint
  // The share of light arriving at the texel that stops there (1 minus what passes through a
  // cut-out or glazing), averaged over the footprint; empty when no surface lets light through.
  std::vector<float> opacity;
  std::vector<uint32_t> triangle; // the triangle holding the sample
  std::vector<uint32_t> page;
  std::vector<uint32_t> texel;    // y * page width + x
  std::vector<uint8_t> flags;
  std::vector<float> offset;      // metres: how far rays start above the surface to avoid self-hits
  // For elements near geometry: which cells of a 4 x 4 grid over the texel the sample point sees
  // along the surface and are on its side of any cover (bit 4 * row + column); rays start only
  // from those. All ones elsewhere.
  std::vector<uint16_t> visible_cells;
  // Per page, texel -> element index or -1.
  std::vector<std::vector<int32_t>> element_at;
  // Of the texels that hold more than one triangle and are not one plane, each piece, by element,
  // largest first: where place_samples moves a sample that lies buried (a window frame's face
  // pressed against its reveal, its stepped profile, finer than a texel, hinged onto it). Built by
  // build_elements for place_samples, which empties it.
  struct Piece {
    uint32_t element, triangle;
    Vec2 bary;   // the piece's centroid on its triangle
    float area;  // texels^2 of the page
  };
  std::vector<Piece> other_pieces;
  // The valid samples by the cell of a grid `sample_cell` metres wide that holds them, sorted by
  // key (nearby_samples.h); built by place_samples.
  float sample_cell = 0;
  std::vector<uint64_t> sample_cell_key;
  std::vector<uint32_t> sample_cell_element;

  size_t size() const { return area.size(); }
  bool valid(size_t i) const { return !(flags[i] & kBuried); }
};

// Elements [begin, end) of a stage's share of the work (shared_stage.h); the default is all.
struct ElementRange {
  size_t begin = 0, end = SIZE_MAX;
  ElementRange within(size_t count) const { return {std::min(begin, count), std::min(end, count)}; }
  size_t size() const { return end - begin; }
};

// Which texels average their material over their footprint (the others read it at their sample).
enum class FootprintFilter {
  WhereMaterialsVary,  // texels holding a textured or vertex-coloured triangle, or two materials
  BetweenMaterials,    // only texels holding two materials: the plan found no texture or vertex colour
  Everywhere,          // every texel, constant material or not: the full simulation
};

struct ElementOptions {
  int footprint_samples = 4;  // per side: footprint_samples^2 material samples per filtered texel
  FootprintFilter filter = FootprintFilter::WhereMaterialsVary;
};

// How far rays start above a surface point: a fraction of the texel, but never below what float
// precision at this distance from the origin can resolve (scenes in kilometres stay clean).
float ray_offset(Vec3 p, float texel_size);

// Rasterises every triangle into its page and makes one element per covered texel.
Elements build_elements(const Surface& surface, const MaterialSampler& materials, const ElementOptions& options,
                        Progress& progress);

// Moves samples that sit behind nearby geometry (a floor texel straddling a wall) to its front,
// flags samples buried inside closed geometry, and records which neighbouring texels are not
// separated by geometry, so no light or shadow leaks through a wall standing on a surface.
// Likewise for covers: a texel across a cover's edge keeps only its sample's side, the area of
// the other going to a neighbour on that side, and texels under a cover join none in the open, so
// light in a gap (a double-sided lamp's back under the ceiling) stays there.
void place_samples(Elements& elements, const Surface& surface, const RayTracer& tracer, uint64_t seed,
                   Progress& progress);

// Whether another surface lies over `point` (on triangle `triangle`, lifted by its ray offset)
// within a sixteenth of a texel along the triangle's normal: a gap so thin that its light stays in
// it. Mixed with the open surface beside it, in a texel across its edge, it would be shone out.
bool under_cover(const Surface& surface, const RayTracer& tracer, uint32_t triangle, Vec3 point);

// Whether point `to` on triangle `to_triangle` is in sight of point `from` on `from_triangle` (both
// lifted off their surfaces) within one texel's surface. A chart is one piece of surface under its
// texels, its slivers hinged on whatever their angle (a window frame's stepped profile onto its
// face): its own steps and corners are the detail a texel stands for, so between two points of
// one chart whose faces are less than 120 degrees apart its own faces do not block the line. Faces
// further apart are two sides of something thin (a door leaf, a table top, both faces in one
// chart), and the line between them passes through it: there every face blocks.
bool sees_within_texel(const Surface& surface, const RayTracer& tracer, Vec3 from, uint32_t from_triangle, Vec3 to,
                       uint32_t to_triangle);

// Whether `point` (lifted off its surface, whose geometric normal is `ng`) is inside geometry: it
// sees back faces in half its hemisphere (16 cosine-weighted rays stratified by `pattern`).
bool buried_at(const RayTracer& tracer, Vec3 point, Vec3 ng, uint32_t pattern);

// The element whose texel holds point `bary` of `triangle` (buried ones included), or -1.
int64_t element_at_point(const Elements& elements, const Surface& surface, uint32_t triangle, Vec2 bary);

// The surface point of the element's triangle at sub-texel position u in [0,1)^2, if it has one.
bool footprint_surface_point(const Elements& elements, const Surface& surface, size_t element, Vec2 u, Vec3& point);

// A point of the element's footprint for sub-texel sample u in [0,1)^2: on the element's triangle
// in a cell the sample point sees (u in a cell it does not see is moved to one it does), else the
// sample point itself.
Vec3 footprint_point(const Elements& elements, const Surface& surface, size_t element, Vec2 u);

}  // namespace radbake

#include "hard_cases/hard_case_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace radbake::test {
namespace {

bool finite_and_non_negative(Rgb v) { return is_finite(v) && v.x >= 0 && v.y >= 0 && v.z >= 0; }

// Counts the values that fail, reporting the first three by `where`.
class Offenders {
 public:
  explicit Offenders(const char* kind) : kind_(kind) {}
  ~Offenders() { EXPECT_EQ(count_, 0u) << kind_ << " values that are NaN, infinite or negative"; }
  template <typename Where>
  void check(Rgb v, Where where) {
    if (finite_and_non_negative(v)) return;
    if (++count_ <= 3) ADD_FAILURE() << kind_ << " " << where() << " = (" << v.x << ", " << v.y << ", " << v.z << ")";
  }

 private:
  const char* kind_;
  size_t count_ = 0;
};

}  // namespace

void expect_finite_and_non_negative(const BakeResult& r) {
  {
    Offenders bad("element irradiance");
    for (size_t i = 0; i < r.elements.size(); ++i)
      if (r.elements.valid(i)) bad.check(r.irradiance[i], [&] { return "of element " + std::to_string(i); });
  }
  {
    Offenders bad("page texel");
    for (size_t p = 0; p < r.pages.size(); ++p)
      for (size_t t = 0; t < r.pages[p].texels.size(); ++t)
        bad.check(r.pages[p].texels[t], [&] { return std::to_string(t) + " of page " + std::to_string(p); });
  }
  {
    Offenders bad("vertex value");
    for (size_t m = 0; m < r.vertex_values.size(); ++m)
      for (size_t v = 0; v < r.vertex_values[m].size(); ++v)
        bad.check(r.vertex_values[m][v], [&] { return std::to_string(v) + " of instance " + std::to_string(m); });
  }
}

double worst_relative_error(const BakeResult& r, const std::function<bool(Vec3, Vec3)>& where,
                            const std::function<double(Vec3, Vec3)>& expected, size_t* count) {
  double worst = 0;
  *count = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    if (!r.elements.valid(i) || !where(r.elements.position[i], r.elements.normal[i])) continue;
    const double e = expected(r.elements.position[i], r.elements.normal[i]);
    worst = std::max(worst, std::fabs(r.irradiance[i].x - e) / e);
    ++*count;
  }
  return worst;
}

}  // namespace radbake::test

// Where the radiosity solve stops. A small room that a large sunlit ground lights through a window
// is one enclosure with the ground, whose input dwarfs the room's: held to that input, the room's
// light stopped mostly unshot (bench/window_room's rooms read 4-6% dark at preview). Each patch is
// held to its own light instead; checked against the closed form of a two-part scene. And the
// same equation for many sources at once (solve_columns, a year of daylight's sky patches and sun
// bins), against that closed form and against one solve per source.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "baker/transport/interreflection.h"
#include "baker/transport/solve_columns.h"
#include "baker/transport/solve_radiosity.h"

namespace radbake {
namespace {

// One ground patch of 100 m2 (reflectance 0.3, 30,000 lux direct) and six room patches of 4 m2
// (reflectance 0.7, no direct light). The ground sends 0.0004 of its light to each room patch
// (the window), the rest to the sky; each room patch sends 0.01 back to the ground (reciprocity:
// 100 x 0.0004 = 4 x 0.01) and 0.18 to each of the other five.
constexpr float kGroundArea = 100, kRoomArea = 4, kGroundRho = 0.3f, kRoomRho = 0.7f, kDirect = 30000;
constexpr float kGroundToRoom = 0.0004f, kRoomToGround = 0.01f, kRoomToRoom = 0.18f;
constexpr int kRoomPatches = 6;

struct TwoParts {
  Patches patches;
  PatchTransport transport;
  std::vector<Rgb> direct;
};

TwoParts ground_and_room() {
  TwoParts s;
  const int n = 1 + kRoomPatches;
  for (int p = 0; p < n; ++p) {
    const bool ground = p == 0;
    const float rho = ground ? kGroundRho : kRoomRho;
    s.patches.area.push_back(ground ? kGroundArea : kRoomArea);
    s.patches.reflectance.push_back({rho, rho, rho});
    s.patches.emission.push_back({});
    s.patches.side.push_back(1);
    s.direct.push_back(ground ? Rgb{kDirect, kDirect, kDirect} : Rgb{});
    s.transport.row_start.push_back(s.transport.target.size());
    for (int q = 0; q < n; ++q) {
      if (q == p) continue;
      s.transport.target.push_back(uint32_t(q));
      s.transport.form_factor.push_back(ground ? kGroundToRoom : (q == 0 ? kRoomToGround : kRoomToRoom));
    }
  }
  s.transport.row_start.push_back(s.transport.target.size());
  return s;
}

// The closed form: by symmetry every room patch has one exitance B_r = rho_r (F_rg B_g + 5 f B_r),
// and the ground B_g = rho_g (D + 6 F_gr B_r).
struct Exact {
  double ground, room;
};
Exact exact() {
  const double k = kRoomRho * kRoomToGround / (1.0 - (kRoomPatches - 1) * kRoomRho * kRoomToRoom);
  const double ground = kGroundRho * kDirect / (1.0 - kRoomPatches * kGroundRho * kGroundToRoom * k);
  return {ground, k * ground};
}

class SolveStops : public ::testing::TestWithParam<Solver> {};

TEST_P(SolveStops, EachPatchWithinItsOwnToleranceWhereALargeInputSharesItsEnclosure) {
  const TwoParts s = ground_and_room();
  SolveOptions options;  // the default tolerance, 0.1%, and the ambient term
  options.solver = GetParam();
  Progress progress;
  const RadiositySolution solution = solve_radiosity(s.patches, s.transport, s.direct, options, progress);
  ASSERT_TRUE(solution.converged);
  const Exact want = exact();
  // What a patch may still be owed when it stops: the tolerance of its own light from each patch
  // it sees, multiplied by the room's further bounces, 1 / (1 - 5 x 0.7 x 0.18) = 2.7: 0.3%; 1%
  // bounds it with room for the ambient term. Held to the whole enclosure's input, the room's
  // patches stopped at 45% of their light when shooting, 8% with Jacobi sweeps.
  EXPECT_NEAR(solution.exitance[0].x / want.ground, 1.0, 0.01);
  for (int p = 1; p <= kRoomPatches; ++p)
    EXPECT_NEAR(solution.exitance[size_t(p)].x / want.room, 1.0, 0.01) << "room patch " << p;
}

INSTANTIATE_TEST_SUITE_P(Solvers, SolveStops,
                         ::testing::Values(Solver::Shooting, Solver::GaussSeidel, Solver::Jacobi),
                         [](const ::testing::TestParamInfo<Solver>& info) {
                           return std::string(info.param == Solver::Shooting      ? "Shooting"
                                              : info.param == Solver::GaussSeidel ? "GaussSeidel"
                                                                                  : "Jacobi");
                         });

// The two-part scene's ground lit as by 1, 2 and 0.5 of kDirect, three columns at once.
TEST(SolveColumns, EachColumnWithinItsOwnToleranceOfTheClosedForm) {
  const TwoParts s = ground_and_room();
  const size_t n = s.patches.size(), columns = 3;
  const float scale[columns] = {1.0f, 2.0f, 0.5f};
  std::vector<float> direct(n * columns, 0.0f);
  for (size_t c = 0; c < columns; ++c) direct[0 * columns + c] = kDirect * scale[c];
  const ColumnSolution solved = solve_columns(s.patches, s.transport, direct, columns, SolveOptions{});
  ASSERT_TRUE(solved.converged);
  const Exact want = exact();
  for (size_t c = 0; c < columns; ++c) {
    // A room patch gathers B_r / rho_r (it has no direct light); the ground, 6 F_rg B_r A_r / A_g,
    // which is 6 F_gr B_r by reciprocity. 1%: the bound of SolveStops above, the tolerance carried through the
    // room's bounces with room for the ambient term.
    for (size_t p = 1; p < n; ++p)
      EXPECT_NEAR(solved.gathered[p * columns + c].x / (scale[c] * want.room / kRoomRho), 1.0, 0.01)
          << "column " << c << ", room patch " << p;
    EXPECT_NEAR(solved.gathered[0 * columns + c].x / (scale[c] * kRoomPatches * kGroundToRoom * want.room), 1.0, 0.01)
        << "column " << c << ", the ground";
  }
}

// 40 patches of coloured reflectance exchanging light at random (row sums up to 0.9), 70 columns
// of random direct light: more than one block of columns, and the last block part-filled.
struct RandomScene {
  Patches patches;
  PatchTransport transport;
  std::vector<float> direct;  // [patch * columns + column]
  size_t columns = 70;
};

RandomScene random_scene() {
  RandomScene s;
  const size_t n = 40;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (size_t p = 0; p < n; ++p) {
    s.patches.area.push_back(0.5f + 2 * unit(rng));
    s.patches.reflectance.push_back({0.1f + 0.7f * unit(rng), 0.1f + 0.7f * unit(rng), 0.1f + 0.7f * unit(rng)});
    s.patches.emission.push_back({});
    s.patches.side.push_back(1);
    s.transport.row_start.push_back(s.transport.target.size());
    std::vector<float> row(n);
    float total = 0;
    for (size_t q = 0; q < n; ++q) total += row[q] = q == p || unit(rng) < 0.5f ? 0.0f : unit(rng);
    for (size_t q = 0; q < n; ++q)
      if (row[q] > 0) {
        s.transport.target.push_back(uint32_t(q));
        s.transport.form_factor.push_back(0.9f * row[q] / total);
      }
  }
  s.transport.row_start.push_back(s.transport.target.size());
  s.direct.resize(n * s.columns);
  for (float& d : s.direct) d = unit(rng) < 0.3f ? 1000 * unit(rng) : 0.0f;
  return s;
}

TEST(SolveColumns, EachColumnAndChannelAsItsOwnSolve) {
  const RandomScene s = random_scene();
  const size_t n = s.patches.size();
  SolveOptions tight;  // both solves near exact, so what is left is any error in the equation
  tight.tolerance = 1e-6;
  const ColumnSolution solved = solve_columns(s.patches, s.transport, s.direct, s.columns, tight);
  ASSERT_TRUE(solved.converged);
  for (size_t c = 0; c < s.columns; ++c) {
    std::vector<Rgb> direct(n);
    for (size_t p = 0; p < n; ++p) direct[p] = Rgb{1, 1, 1} * s.direct[p * s.columns + c];
    Progress quiet;
    const RadiositySolution one = solve_radiosity(s.patches, s.transport, direct, tight, quiet);
    const std::vector<Rgb> want = gathered_irradiance(s.patches, s.transport, one.exitance);
    for (size_t p = 0; p < n; ++p)
      for (int k = 0; k < 3; ++k)
        // 1e-4 of the light, or 1e-3 lux: float sums over 40 sources after two near-exact solves.
        EXPECT_NEAR(solved.gathered[p * s.columns + c][k], want[p][k], 1e-4 * want[p][k] + 1e-3)
            << "column " << c << ", patch " << p << ", channel " << k;
  }
}

TEST(SolveColumns, TheSameOnOneThreadAsOnMany) {
  const RandomScene s = random_scene();
  const ColumnSolution many = solve_columns(s.patches, s.transport, s.direct, s.columns, SolveOptions{});
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const ColumnSolution one = solve_columns(s.patches, s.transport, s.direct, s.columns, SolveOptions{});
  ASSERT_EQ(one.gathered.size(), many.gathered.size());
  for (size_t k = 0; k < one.gathered.size(); ++k) {
    EXPECT_EQ(one.gathered[k].x, many.gathered[k].x) << k;
    EXPECT_EQ(one.gathered[k].z, many.gathered[k].z) << k;
  }
}

}  // namespace
}  // namespace radbake

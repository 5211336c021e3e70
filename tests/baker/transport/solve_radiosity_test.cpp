// Where the radiosity solve stops. A small room that a large sunlit ground lights through a window
// is one enclosure with the ground, whose input dwarfs the room's: held to that input, the room's
// light stopped mostly unshot (bench/window_room's rooms read 4-6% dark at preview). Each patch is
// held to its own light instead; checked against the closed form of a two-part scene.
#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace radbake

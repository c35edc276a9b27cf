#pragma once
#include <array>

namespace lbm {

// D3Q19 velocity set as compile-time constants. Order: rest, 6 axis directions, 12 edge
// diagonals; opposite directions are adjacent pairs (q, q+1) for q odd, which keeps the
// TRT symmetric/antisymmetric split a simple pairwise loop.
struct D3Q19 {
  static constexpr int Q = 19;
  static constexpr double cs2 = 1.0 / 3.0;
  static constexpr int c[Q][3] = {
      {0, 0, 0},                                                       //
      {1, 0, 0},  {-1, 0, 0}, {0, 1, 0},  {0, -1, 0}, {0, 0, 1},  {0, 0, -1},  //
      {1, 1, 0},  {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0},                 //
      {1, 0, 1},  {-1, 0, -1}, {1, 0, -1}, {-1, 0, 1},                 //
      {0, 1, 1},  {0, -1, -1}, {0, 1, -1}, {0, -1, 1}};
  static constexpr double w[Q] = {1.0 / 3.0,  1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0,
                                  1.0 / 18.0, 1.0 / 18.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0,
                                  1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0,
                                  1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0};
  static constexpr int opposite(int q) { return q == 0 ? 0 : (q % 2 == 1 ? q + 1 : q - 1); }
};

}  // namespace lbm

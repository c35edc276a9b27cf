#include "lbm/open_boundary.h"

#include <type_traits>

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "plane_nodes.h"

namespace lbm {

namespace {
// Every fluid node of the face's plane (plane_nodes.h).
template <typename Visit, typename Ahead>
void for_face_nodes(const OpenFace& face, const BlockLayout& layout,
                    const std::vector<std::uint8_t>& node_type, Visit visit, Ahead ahead) {
  detail::for_plane_fluid_nodes(layout, node_type, face.axis, face.local_plane, visit, ahead);
}
// The same split over the OpenMP threads: for apply_face, whose node reads and writes only
// the slots it pulls.
template <typename Visit, typename Ahead>
void for_face_nodes_in_parallel(const OpenFace& face, const BlockLayout& layout,
                                const std::vector<std::uint8_t>& node_type, Visit visit, Ahead ahead) {
  detail::for_plane_fluid_nodes_in_parallel(layout, node_type, face.axis, face.local_plane, visit, ahead);
}

// What a face node knows after streaming, from its populations post[q] = f*_q(x - c_q): the
// sums over the directions along the face (T, with their transverse momenta) and those
// pointing out of the lattice (O). The q loop unrolls and every test of c_q along the normal
// folds away. Inlined into the face's node loop (a call per node there costs more than the sums).
struct KnownSums {
  double tangential = 0.0, outgoing = 0.0;
  double transverse[3] = {0.0, 0.0, 0.0};
};
template <int kAxis, int kInward>
[[gnu::always_inline]] inline KnownSums known_sums(const double* post) {
  using L = D3Q19;
  constexpr int t1 = (kAxis + 1) % 3, t2 = (kAxis + 2) % 3;  // tangential axes
  KnownSums k;
#pragma GCC unroll 19
  for (int q = 0; q < L::Q; ++q) {
    const int cn = L::c[q][kAxis] * kInward;
    if (cn == 0) {
      k.tangential += post[q];
      k.transverse[t1] += post[q] * L::c[q][t1];
      k.transverse[t2] += post[q] * L::c[q][t2];
    } else if (cn < 0) {
      k.outgoing += post[q];
    }
  }
  return k;
}

// The node's density rho, its velocity along the inward normal u_n and the momentum density m
// (m u_n the normal momentum) that the face imposes, from what the node knows.
struct ImposedState {
  double rho, u_n, m;
};
template <int kInward>
[[gnu::always_inline]] inline ImposedState imposed_state(const OpenFace& face, const KnownSums& k) {
  // u_n is the velocity along the inward normal; rho = T + O + I and m u_n = I - O with
  // m = rho (standard) or rho0 (incompressible), so rho - m u_n = T + 2 O.
  double rho, u_n, m;
  const double known = k.tangential + 2.0 * k.outgoing;
  if (face.momentum_density > 0.0) {
    m = face.momentum_density;
    if (face.kind == OpenFace::kVelocity) {
      u_n = face.value * kInward;
      rho = known + m * u_n;
    } else {
      rho = face.value;
      u_n = (rho - known) / m;
    }
  } else if (face.kind == OpenFace::kVelocity) {
    u_n = face.value * kInward;
    rho = m = known / (1.0 - u_n);
  } else {
    rho = m = face.value;
    u_n = 1.0 - known / rho;
  }
  return {rho, u_n, m};
}

// One face, its axis and inward direction known at compile time: the q loops unroll and
// every test of c_q along the normal folds away (the same sums in the same order as the
// loops over q with those tests at run time; every product with a c_q component is exact).
template <int kAxis, int kInward>
void apply_face(const OpenFace& face, const BlockLayout& layout,
                const std::vector<std::uint8_t>& node_type, PopulationField& f, double* density) {
  using L = D3Q19;
  constexpr int a = kAxis;
  constexpr int t1 = (a + 1) % 3, t2 = (a + 2) % 3;  // tangential axes
  std::ptrdiff_t off[L::Q];
  // pulled[q][x] = f_q(x - c_q): the population x pulls, taken once per face.
  Real* pulled[L::Q];
  for (int q = 0; q < L::Q; ++q) {
    off[q] = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
    pulled[q] = f.q(q) - off[q];
  }

  // The lines of the node a few places ahead are asked for while this one is computed: on
  // an x-normal face each is a line of its own, just streamed to memory by the kernel.
  const auto prefetch = [&](std::size_t ahead) { detail::prefetch_pulled(f, ahead, off); };
  // A node reads and writes only the slots it pulls: the nodes may go to any thread.
  for_face_nodes_in_parallel(face, layout, node_type, [&](std::size_t cell, std::size_t slot) {
    // Populations after streaming: f_q(x) = f*_q(x - c_q).
    double post[L::Q];
#pragma GCC unroll 19
    for (int q = 0; q < L::Q; ++q) post[q] = pulled[q][cell];
    const KnownSums k = known_sums<kAxis, kInward>(post);
    const ImposedState state = imposed_state<kInward>(face, k);
    if (density) density[slot] = state.rho;
    double u[3] = {0.0, 0.0, 0.0};
    u[a] = state.u_n * kInward;
    // Transverse momentum correction N_t = 1/2 sum_{c.n=0} f c_t - rho u_t / 3 (u_t = 0).
    const double n1 = 0.5 * k.transverse[t1], n2 = 0.5 * k.transverse[t2];
#pragma GCC unroll 19
    for (int q = 0; q < L::Q; ++q) {
      if (L::c[q][a] * kInward <= 0) continue;  // known
      const int qo = L::opposite(q);
      const double cu = L::c[q][0] * u[0] + L::c[q][1] * u[1] + L::c[q][2] * u[2];
      const double value =
          post[qo] + 6.0 * L::w[q] * state.m * cu - (L::c[q][t1] * n1 + L::c[q][t2] * n2);
      pulled[q][cell] = static_cast<Real>(value);
    }
  }, prefetch);
}

template <int kAxis, int kInward>
double node_density(const OpenFace& face, const BlockLayout& layout, const PopulationField& f,
                    std::size_t cell) {
  using L = D3Q19;
  double post[L::Q];
  for (int q = 0; q < L::Q; ++q)
    post[q] = f.q(q)[cell - layout.offset(L::c[q][0], L::c[q][1], L::c[q][2])];
  return imposed_state<kInward>(face, known_sums<kAxis, kInward>(post)).rho;
}

template <int kAxis, int kInward>
double face_mass(const OpenFace& face, const BlockLayout& layout,
                 const std::vector<std::uint8_t>& node_type, const PopulationField& f) {
  using L = D3Q19;
  constexpr int a = kAxis;
  std::ptrdiff_t off[L::Q];
  const Real* own[L::Q];
  for (int q = 0; q < L::Q; ++q) {
    off[q] = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
    own[q] = f.q(q);
  }
  const std::uint8_t* const type = node_type.data();
  double mass = 0.0;
  for_face_nodes(face, layout, node_type, [&](std::size_t cell) {
#pragma GCC unroll 19
    for (int q = 1; q < L::Q; ++q) {
      if (L::c[q][a] * kInward > 0 && type[cell - off[q]] == kOpen)
        mass += own[q][cell - off[q]];  // pulled from beyond the face
      else if (L::c[q][a] * kInward < 0 && type[cell + off[q]] == kOpen)
        mass -= own[q][cell];  // sent beyond the face: lost
    }
  }, [](std::size_t) {});  // the lines apply_open_face has just read
  return mass;
}

// call(axis, inward) with both as compile-time constants (std::integral_constant): the
// face's instance for its axis and direction.
template <typename Call>
auto by_face(const OpenFace& face, Call call) {
  using std::integral_constant;
  const bool in = face.inward > 0;
  switch (face.axis) {
    case 0: return in ? call(integral_constant<int, 0>{}, integral_constant<int, +1>{})
                      : call(integral_constant<int, 0>{}, integral_constant<int, -1>{});
    case 1: return in ? call(integral_constant<int, 1>{}, integral_constant<int, +1>{})
                      : call(integral_constant<int, 1>{}, integral_constant<int, -1>{});
    default: return in ? call(integral_constant<int, 2>{}, integral_constant<int, +1>{})
                       : call(integral_constant<int, 2>{}, integral_constant<int, -1>{});
  }
}
}  // namespace

void apply_open_face(const OpenFace& face, const BlockLayout& layout,
                     const std::vector<std::uint8_t>& node_type, PopulationField& f, double* density) {
  by_face(face, [&](auto axis, auto inward) {
    apply_face<decltype(axis)::value, decltype(inward)::value>(face, layout, node_type, f, density);
  });
}

double open_face_node_density(const OpenFace& face, const BlockLayout& layout, const PopulationField& f,
                              std::size_t cell) {
  return by_face(face, [&](auto axis, auto inward) {
    return node_density<decltype(axis)::value, decltype(inward)::value>(face, layout, f, cell);
  });
}

double open_face_mass(const OpenFace& face, const BlockLayout& layout,
                      const std::vector<std::uint8_t>& node_type, const PopulationField& f) {
  return by_face(face, [&](auto axis, auto inward) {
    return face_mass<decltype(axis)::value, decltype(inward)::value>(face, layout, node_type, f);
  });
}

}  // namespace lbm

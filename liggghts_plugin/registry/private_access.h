#pragma once
// Access to LIGGGHTS's private style maps without patching LIGGGHTS.
//
// C++ waives access checking for the template arguments of an explicit instantiation
// ([temp.explicit]/12 in C++17): `template struct Steal<Tag, &Modify::fix_map>;` may name the
// private member. The instantiation defines a friend function returning that member pointer,
// which the rest of the code calls through the tag. Only the two maps of Modify are private;
// Force::pair_map is public.
#include <map>
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
class Compute;
class Modify;
}  // namespace LAMMPS_NS

namespace lbm_pore {

// Same function types as Modify's private FixCreator / ComputeCreator typedefs.
using FixCreator = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);
using ComputeCreator = LAMMPS_NS::Compute* (*)(LAMMPS_NS::LAMMPS*, int, int, char**);

struct ModifyFixMapTag {
  using type = std::map<std::string, FixCreator>* LAMMPS_NS::Modify::*;
  friend type member_pointer(ModifyFixMapTag);
};
struct ModifyComputeMapTag {
  using type = std::map<std::string, ComputeCreator>* LAMMPS_NS::Modify::*;
  friend type member_pointer(ModifyComputeMapTag);
};

template <typename Tag, typename Tag::type Member>
struct StealMemberPointer {
  friend typename Tag::type member_pointer(Tag) { return Member; }
};

}  // namespace lbm_pore

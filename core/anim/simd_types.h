#pragma once
// The SIMD vector types of anim/simd.h alone, for headers that keep such vectors as members:
// anim/simd.h's eight-lane helpers make GCC note an ABI change in every file that includes it.

namespace thespis::core::anim::simd {

using F4 = float __attribute__((vector_size(16)));
using I4 = int __attribute__((vector_size(16)));
using F8 = float __attribute__((vector_size(32))); // see anim/simd.h's "Eight lanes"
using I8 = int __attribute__((vector_size(32)));

} // namespace thespis::core::anim::simd

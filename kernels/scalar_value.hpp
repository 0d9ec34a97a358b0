#pragma once
// The value part of a kernel scalar: the double itself, or the value of a Sacado Fad (.val()),
// for decisions (branches, pivots, iteration counts) that a kernel takes on values whatever
// the scalar it runs in.

#include "kernels/kernel_macros.hpp"

namespace grout {

GROUT_INLINE_FUNCTION double value_of(double x) {
  return x;
}

template <class Scalar>
GROUT_INLINE_FUNCTION auto value_of(const Scalar& x) -> decltype(x.val()) {
  return x.val();
}

}  // namespace grout

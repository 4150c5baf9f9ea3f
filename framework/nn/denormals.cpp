// Flush-to-zero scope (see nn/denormals.hpp).
#include "nn/denormals.hpp"

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define CORRMP_NN_HAVE_MXCSR 1
#endif

namespace corrmp::nn {

#ifdef CORRMP_NN_HAVE_MXCSR
namespace {
constexpr unsigned int kFlushToZero = 0x8000u;       // MXCSR.FTZ
constexpr unsigned int kDenormalsAreZero = 0x0040u;  // MXCSR.DAZ
}  // namespace

ScopedFlushDenormals::ScopedFlushDenormals() : saved_control_(_mm_getcsr()) {
  _mm_setcsr(saved_control_ | kFlushToZero | kDenormalsAreZero);
}

ScopedFlushDenormals::~ScopedFlushDenormals() { _mm_setcsr(saved_control_); }
#else
ScopedFlushDenormals::ScopedFlushDenormals() = default;
ScopedFlushDenormals::~ScopedFlushDenormals() = default;
#endif

}  // namespace corrmp::nn

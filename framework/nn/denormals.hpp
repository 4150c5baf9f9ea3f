// Flush-to-zero for subnormal floats, which x86 CPUs process in slow microcode: late in CNMP
// training many gradients and Adam second moments decay into the subnormal range and can more
// than double the cost of an update. Training loops may hold a ScopedFlushDenormals for the
// whole loop; Adam::step (nn/adam.hpp) holds one itself.
//
// Inside the scope, subnormal inputs read as zero (DAZ) and subnormal results become zero
// (FTZ) on the current thread. Subnormal floats are below 1.2e-38, so for Adam this only drops
// updates far smaller than lr * 1e-30 (sqrt(v) of a subnormal v is < 1.1e-19, far below eps).
// On targets without SSE control registers the scope does nothing.
#pragma once

namespace corrmp::nn {

class ScopedFlushDenormals {
 public:
  ScopedFlushDenormals();
  ~ScopedFlushDenormals();
  ScopedFlushDenormals(const ScopedFlushDenormals&) = delete;
  ScopedFlushDenormals& operator=(const ScopedFlushDenormals&) = delete;

 private:
  unsigned int saved_control_ = 0;
};

}  // namespace corrmp::nn

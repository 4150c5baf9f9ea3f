// Growable activation storage that keeps training steps free of heap allocation.
//
// A Buffer owns a flat array and hands out row-major views of any shape that fits in it. The
// array grows only when a requested shape needs more elements than it holds and never shrinks,
// so once a step has run with its largest batch, later steps (with the same or smaller batches,
// e.g. a CNMP conditioned on a varying number of observations) reuse the same memory.
#pragma once

#include <stdexcept>

#include "nn/tensor.hpp"

namespace corrmp::nn {

template <class S>
class Buffer {
 public:
  /// Shapes the buffer as rows x cols and returns a view of it. Grows the storage only when
  /// rows * cols exceeds capacity(). The contents are unspecified after a resize.
  MatMap<S> resize(Index rows, Index cols) {
    const Index needed = rows * cols;
    if (needed > storage_.size()) storage_.resize(needed);
    rows_ = rows;
    cols_ = cols;
    return view();
  }

  /// A rows x cols view of the storage that leaves the buffer's shape as it is, for threads
  /// that share a buffer (nn/team.hpp): the storage must already hold rows * cols elements.
  MatMap<S> shaped(Index rows, Index cols) {
    if (rows * cols > storage_.size())
      throw std::logic_error("Buffer::shaped: larger than storage");
    return MatMap<S>(storage_.data(), rows, cols);
  }

  /// The current shape as a writable view.
  MatMap<S> view() { return MatMap<S>(storage_.data(), rows_, cols_); }
  /// The current shape as a read-only view.
  ConstMatMap<S> view() const { return ConstMatMap<S>(storage_.data(), rows_, cols_); }

  Index rows() const { return rows_; }
  Index cols() const { return cols_; }
  /// Number of elements the storage can hold without reallocating.
  Index capacity() const { return storage_.size(); }

 private:
  Vec<S> storage_;
  Index rows_ = 0;
  Index cols_ = 0;
};

}  // namespace corrmp::nn

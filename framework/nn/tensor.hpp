// Matrix types and the memory-layout convention shared by every layer of corrmp::nn.
//
// Layout: activations are batch-major, row-major matrices. Row n of a matrix is sample n of
// the batch; its columns are that sample's features. An image batch (NCHW) is stored the same
// way: row n holds image n flattened in C, H, W order (index (c * H + h) * W + w), so Flatten
// is the identity and a convolution can view one row as a C x (H * W) row-major matrix.
//
// Layers take inputs as ConstMatRef and write outputs into MatRef. Both bind without a copy
// to Mat, to Eigen::Map<Mat> (see nn/buffer.hpp) and to row/column blocks of them. Passing a
// column-major matrix to a ConstMatRef silently makes a temporary copy (a heap allocation);
// use the row-major types below to keep training steps allocation-free.
#pragma once

#include <Eigen/Core>

namespace corrmp::nn {

using Index = Eigen::Index;

/// A batch-major (row = sample) dense matrix.
template <class S>
using Mat = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// A flat parameter or state vector.
template <class S>
using Vec = Eigen::Matrix<S, Eigen::Dynamic, 1>;

/// A writable view of a row-major matrix, a Map of one, or a block of either.
template <class S>
using MatRef = Eigen::Ref<Mat<S>>;

/// A read-only view of a row-major matrix, a Map of one, or a block of either.
template <class S>
using ConstMatRef = Eigen::Ref<const Mat<S>>;

/// A view of caller- or layer-owned storage shaped as a row-major matrix.
template <class S>
using MatMap = Eigen::Map<Mat<S>>;

/// A read-only view of storage shaped as a row-major matrix.
template <class S>
using ConstMatMap = Eigen::Map<const Mat<S>>;

/// A view of storage shaped as a row-major matrix whose rows lie `outer stride` values apart
/// (e.g. a run of columns of a wider row-major matrix).
template <class S>
using StridedMap = Eigen::Map<Mat<S>, 0, Eigen::OuterStride<>>;

/// Read-only version of StridedMap.
template <class S>
using ConstStridedMap = Eigen::Map<const Mat<S>, 0, Eigen::OuterStride<>>;

}  // namespace corrmp::nn

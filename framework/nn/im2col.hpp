// Patch unfolding (im2col) and folding (col2im), which turn Conv2d and ConvTranspose2d into
// matrix products (nn/conv2d.hpp, nn/conv_transpose2d.hpp).
//
// For a PatchGeometry g over an image X (C x H x W, stored C, H, W order) the column matrix
// `cols` is row-major with g.patch_size() rows and g.positions() columns:
//   cols[(c k + i) k + j][oh Wo + ow] = X[c][oh s - p + i][ow s - p + j]   (0 outside X)
// im2col writes cols from X. col2im is its adjoint: it writes X[c][h][w] = the sum of all
// cols entries that im2col would read from (c, h, w), so <im2col(X), Y> = <X, col2im(Y)>.
#pragma once

#include "nn/conv_geometry.hpp"

namespace corrmp::nn {

/// Unfolds `image` (g.image.size() values) into `cols` (g.patch_size() * g.positions()).
template <class S>
void im2col(const S* image, const PatchGeometry& g, S* cols);

/// Folds `cols` back into `image`, overwriting it with the adjoint of im2col.
template <class S>
void col2im(const S* cols, const PatchGeometry& g, S* image);

}  // namespace corrmp::nn

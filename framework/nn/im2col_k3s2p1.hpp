// im2col and col2im for the autoencoder's downsampling geometry (paper, Section "Learning the
// Context": kernel 3, stride 2, padding 1 on an image of twice the output size), written out
// for that geometry; nn/im2col.cpp sends the chunks of such layers here. Same contract as
// im2col_chunk and col2im_chunk (nn/im2col.hpp).
#pragma once

#include "nn/im2col.hpp"

namespace corrmp::nn {

/// Whether g is kernel 3, stride 2, padding 1 on an image of exactly twice the output size.
bool is_k3s2p1(const PatchGeometry& g);

/// im2col_chunk for a geometry with is_k3s2p1.
template <class S>
void unfold_k3s2p1(const S* images, Index image_stride, const PatchGeometry& g,
                   const PositionChunk& chunk, S* cols);

/// col2im_chunk for a geometry with is_k3s2p1.
template <class S>
void fold_k3s2p1(const S* cols, const PatchGeometry& g, const PositionChunk& chunk, S* images,
                 Index image_stride, const S* channel_bias);

}  // namespace corrmp::nn

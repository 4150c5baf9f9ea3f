// On-disk cache of collected demonstrations, keyed by a hash of what determines
// them (the environment and demonstrations sections and the root seed), so
// reruns and sweeps over policy or context parameters reuse them. Lossless:
// doubles and depth are stored bit for bit and colour images as PNG, so a cached run gives the
// same results as a fresh one.
//
// Format (little-endian): "CMPD", uint32 version, uint64 demonstration count for
// train then validation, then per demonstration: string scenario, string
// decision, uint32 segments, per segment: string name, matrix x, matrix y,
// vector context, double phase_begin, phase_end, uint32 state entries (string,
// double), PNG rgb, depth as uint32 rows, cols and raw float32, uint8 camera
// flag (then int32 width, height, double fx, fy, cx, cy, near, far and the
// column-major 4x4 world_from_camera); strings and blobs are uint64 length +
// bytes. Then an FNV-1a checksum of everything before. Version 3.
#pragma once

#include <optional>
#include <string>

#include "data/demonstrations.hpp"

namespace corrmp {

// Writes the cache atomically (core/atomic_file.hpp). A cache only saves
// time: one that cannot be written (a full disk, a directory in its place) is
// a warning naming the file, and false is returned; the run goes on.
bool save_demonstrations(const std::string& path, const DemonstrationSplit& demos);
// The cached demonstrations, or nothing when the file is missing; throws a
// one-line std::runtime_error "demonstration cache '<path>': <problem>" when
// it cannot be used: a directory or other non-regular file, unreadable, empty,
// not a cache file, a checksum mismatch (truncated or damaged), an unsupported
// version. The caller reports it and collects again. Temporary files of a
// killed writer are never read (core/atomic_file.hpp).
std::optional<DemonstrationSplit> load_demonstrations(const std::string& path);

}  // namespace corrmp

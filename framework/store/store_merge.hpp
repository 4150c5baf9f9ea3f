// Merging result databases: the shards a Slurm job array writes (one per task)
// into one. docs/sweeps.md, "Merging shards".
#pragma once

#include <string>
#include <vector>

#include "store/result_store.hpp"

namespace corrmp {

struct MergeCounts {
  int added = 0;       // runs copied with their trials and metrics
  int present = 0;     // runs the target already held (same uid)
  int unfinished = 0;  // runs still 'running' in a shard: left for a later merge
};

// Copies every finished run of `shard` (with its trials and metrics) and its
// sweeps into `target`, unless `target` already holds it: runs are matched by
// their uid, so merging the same shard twice changes nothing. One transaction
// per shard.
MergeCounts merge_shard(ResultStore& target, const std::string& shard);

// Throws StoreError naming `shard` unless it is a result database that merge_shard can read
// (the runs, trials and metrics tables, a schema this program knows); changes nothing in it.
// Checking every shard first refuses a bad one before anything is merged or the target made.
void check_shard(const std::string& shard);

}  // namespace corrmp

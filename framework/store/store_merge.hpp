// Merging result databases: the shards a Slurm job array writes (one per task)
// into one. docs/slurm.md, "Merging the shards".
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

// Throws StoreError naming the first of `shards` that cannot be merged into the database at
// `target_path`: the target itself (under any spelling or link), a missing file, one that is
// not a result database (tables or columns missing), a newer schema, a damaged page. Only
// reads the shards (shard_reader.hpp), and neither opens nor makes the target.
void check_shards(const std::vector<std::string>& shards, const std::string& target_path);

// Copies every finished run of every shard (with its trials and metrics) and the shards'
// sweeps into `target`, unless `target` already holds the run: runs are matched by their uid
// (for a shard written before runs had one, the uid made from the run's own fields that
// upgrading the shard in place also gives it: run_uid.hpp), so merging
// the same shard twice changes nothing. All the shards in one transaction: when one fails,
// nothing is merged, and the StoreError names the shard when reading it failed, the target when
// writing it did (a full disk, a lock, a row its schema refuses). The shards are only read;
// check them first with check_shards. Returns the counts of each shard, in order.
std::vector<MergeCounts> merge_shards_into(ResultStore& target,
                                           const std::vector<std::string>& shards);

// check_shards and merge_shards_into for one shard.
MergeCounts merge_shard(ResultStore& target, const std::string& shard);

}  // namespace corrmp

// The process's thread budget and a parallel loop over independent tasks (independent
// networks trained concurrently, demonstrations collected in parallel). The budget is how many
// threads the parallel stages of this process may keep busy at once: the cores of the machine
// by default, fewer when several runs share them (run_experiment -j). One exception: with a
// budget of 2 or more, one more thread trains the policy's networks that read no context, one
// after another, from the moment a context extractor starts fitting until they are trained
// (experiment/policy_fitting.hpp).
//
// parallel_for(count, task) calls task(i) once for each i in [0, count) on up to
// min(count, thread_budget()) threads, the calling thread among them, and returns when every
// started task has finished. Tasks start in index order (each thread takes the next index when
// it is free), so the results are the same for every budget as long as each task depends only on
// its index. Errors are deterministic too:
//   - after a task throws, no task of a higher index starts; when all started tasks have
//     finished, the exception of the lowest index is rethrown (the one a sequential loop would
//     have thrown);
//   - each thread checks for Ctrl-C (core/interrupt.hpp) before it starts a task; once a signal
//     arrived no further task starts, and Interrupted is thrown after the running ones finished
//     (unless a task threw, whose exception wins).
// With a budget of 1, or a single task, the tasks run inline on the calling thread. A
// parallel_for inside a task of another one runs inline as well, so nested loops never start
// more threads than the budget.
#pragma once

#include <functional>

namespace corrmp {

// Sets the budget (n >= 1, else std::invalid_argument). Call it before the parallel stages
// start; loops already running keep their threads.
void set_thread_budget(int n);
// The budget: set_thread_budget's value, by default std::thread::hardware_concurrency() (at
// least 1).
int thread_budget();

// The number of threads parallel_for would use for `count` tasks from the calling thread:
// min(count, thread_budget()), 1 inside another loop's task, 0 for no tasks.
int parallel_workers(int count);

// Runs task(index) for index in [0, count) as described above.
void parallel_for(int count, const std::function<void(int index)>& task);

// While one lives on a thread, loops started there run inline, as inside a loop's task: a thread
// the budget does not count (the pipeline's, training the networks that read no context beside a
// context extractor) keeps to itself.
class InlineLoops {
 public:
  InlineLoops();
  ~InlineLoops();
  InlineLoops(const InlineLoops&) = delete;
  InlineLoops& operator=(const InlineLoops&) = delete;

 private:
  bool saved_;
};

// Like parallel_for, on at most `max_workers` threads, also passing the worker (in
// [0, min(max_workers, parallel_workers(count)))) that runs the task: one worker runs its tasks
// one after another, so per-worker resources (an environment) need no lock. Which worker runs
// which index depends on timing: results must not depend on `worker`.
void parallel_for_with_workers(int count, int max_workers,
                               const std::function<void(int index, int worker)>& task);

// Threads of the budget that wait for others' work: a loop's worker that found no task left
// (until the loop's last task ends), and the pipeline's thread waiting for the networks that
// read no context (experiment/policy_fitting.cpp). While one waits, a task that can share its
// work (a CNMP's updates, cnmp/parallel_cnmp_step.hpp) may borrow its core for a second thread;
// the borrower checks now and then whether the lender stopped waiting
// (spare_thread_recalled), and then gives the core back.
class SpareThread {
 public:
  SpareThread();
  ~SpareThread();
  SpareThread(const SpareThread&) = delete;
  SpareThread& operator=(const SpareThread&) = delete;
};

// Takes one waiting thread's core if there is one (true), to give back with
// return_spare_thread(). A borrowed core is not lent twice while its lender waits; once the
// lender stops, its borrower must notice (spare_thread_recalled) before the count is right.
bool borrow_spare_thread();
void return_spare_thread();
// True when a thread whose core was borrowed stopped waiting: the caller, a borrower, has then
// given its core back (as return_spare_thread) and must run alone.
bool spare_thread_recalled();

}  // namespace corrmp

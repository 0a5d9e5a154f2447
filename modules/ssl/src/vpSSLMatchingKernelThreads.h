/*
  Private worker pool of the fast matching function. The calling thread takes part and never waits for a worker
  that has not started yet: on a shared CPU (a vehicle's computer, a loaded CI machine) a fork-join barrier
  (OpenMP) would make every call wait for a descheduled thread, which cost milliseconds per frame here.
*/
#ifndef VP_SSL_MATCHING_KERNEL_THREADS_H
#define VP_SSL_MATCHING_KERNEL_THREADS_H

namespace vpSSLMatchingKernel {
using TaskFn = void (*)(const void *context, int index);

/*
  Runs task(context, i) for every i in [0, n), each exactly once, on the calling thread and at most threads - 1
  pool workers; returns when all are done. Indices are handed out in increasing order, one at a time. When the
  pool is busy with another caller, everything runs on the calling thread.
*/
void parallelFor(int n, unsigned int threads, TaskFn task, const void *context);

//! Same for a callable f(int).
template <class F> void parallelFor(int n, unsigned int threads, const F &f)
{
  parallelFor(
      n, threads, [](const void *c, int i) { (*static_cast<const F *>(c))(i); }, &f);
}

//! Number of hardware threads (at least 1): what a thread count of 0 means.
unsigned int hardwareThreads();
} // namespace vpSSLMatchingKernel

#endif

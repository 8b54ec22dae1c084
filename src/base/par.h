/* par.h - a parallel loop for the build's pure computations (an isosurface's grid points, edge
 * vertices, normals and distances): [0, n) cut into fixed chunks that worker threads take in turn.
 * Each index's result must depend on the index alone (the body writes it to its own slot, or
 * folds it into the worker's own order-independent statistic, such as a maximum), so the result
 * is the same bits for any number of workers. */
#ifndef CIRCE_BASE_PAR_H
#define CIRCE_BASE_PAR_H

#include <stddef.h>

/* The workers to use when the user names none: the machine's online cores (1 when unknown). */
int par_default_workers(void);

/* The body of a loop: indices [begin, end), run by worker `worker` (0 .. workers - 1: the index
 * of its own scratch, never shared with another worker while it runs). */
typedef void (*par_body)(void *ctx, size_t begin, size_t end, int worker);

/* Runs body over [0, n) in chunks of `chunk` indices (the last may be shorter) on up to `workers`
 * threads, the caller's among them, and returns when every chunk is done. workers <= 1, or one
 * chunk only, runs body(ctx, 0, n, 0) on the caller's thread; a thread that cannot be started
 * leaves its chunks to the others. */
void par_for(int workers, size_t n, size_t chunk, par_body body, void *ctx);

#endif

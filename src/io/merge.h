/* merge.h - tiles rendered apart (a farm's job array) assembled into the whole frame, bit for bit.
 * A tile is an EXR whose display window is the full frame and whose data window is the tile
 * (OpenEXR's convention). Tiles must agree on everything that decides the pixels: frame size,
 * channels, and the header attributes listed in MERGE_KEYS (scene hash, seed, samples, method,
 * clock, noise threshold, sampler, part); they must not overlap, and together they must cover the frame. */
#ifndef CIRCE_IO_MERGE_H
#define CIRCE_IO_MERGE_H

#include "base/diag.h"
#include "io/exr.h"

#include <stdbool.h>

/* Header attributes that every tile of one frame must share. */
#define MERGE_KEYS                                                                                           \
	{"circe.scene_hash", "circe.seed", "circe.sampler", "circe.spp", "circe.sss", "circe.clock",                \
	 "circe.noise_threshold", "circe.part"}

/* Tile i of n of a width x height frame: row-major on a grid of cols x rows = n chosen so tiles are
 * as square as possible; sizes differ by at most one pixel in each direction. False when n < 1,
 * i is out of range, or there are more columns or rows than pixels. */
bool merge_tile_rect(int width, int height, int i, int n, exrfile_rect *out);

/* Reads the tiles, checks them and writes the merged image to out_path (atomically). Every refusal
 * is reported to d naming the files involved; missing coverage names each missing rectangle. */
bool merge_tiles(const char *out_path, const char *const *tile_paths, int ntiles, diag *d);

#endif

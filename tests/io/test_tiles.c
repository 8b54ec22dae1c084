/* test_tiles: --tile I/N splits any frame into N row-major tiles that cover it exactly once, with
 * sizes differing by at most one pixel per direction, as square as the factors of N allow. */
#include "check.h"
#include "io/merge.h"

#include <stdbool.h>
#include <stdlib.h>

int main(void)
{
	static const int sizes[][2] = {{640, 480}, {1, 1}, {7, 3}, {1000, 17}, {33, 1000}, {64, 64}};
	for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
		int w = sizes[s][0], h = sizes[s][1];
		unsigned char *hits = calloc((size_t)w * h, 1);
		for (int n = 1; n <= 16; n++) {
			exrfile_rect r;
			if (!merge_tile_rect(w, h, 0, n, &r)) {
				bool fits = false;
				for (int cols = 1; cols <= n; cols++)
					fits |= n % cols == 0 && cols <= w && n / cols <= h;
				CHECK(!fits, "%dx%d could be split into %d tiles but was refused", w, h, n);
				continue;
			}
			for (size_t k = 0; k < (size_t)w * h; k++)
				hits[k] = 0;
			int minw = w, maxw = 0, minh = h, maxh = 0, prev_y0 = -1, prev_x0 = -1;
			for (int i = 0; i < n; i++) {
				CHECK(merge_tile_rect(w, h, i, n, &r), "tile %d/%d of %dx%d", i, n, w, h);
				CHECK(r.x0 >= 0 && r.y0 >= 0 && r.x1 <= w && r.y1 <= h && r.x1 > r.x0 && r.y1 > r.y0,
				      "tile %d/%d of %dx%d inside the frame: %d,%d-%d,%d", i, n, w, h, r.x0, r.y0, r.x1, r.y1);
				/* Row-major: y never decreases; within a row x increases. */
				CHECK(r.y0 > prev_y0 || (r.y0 == prev_y0 && r.x0 > prev_x0), "tile %d/%d is row-major", i, n);
				prev_y0 = r.y0, prev_x0 = r.x0;
				int tw = r.x1 - r.x0, th = r.y1 - r.y0;
				minw = tw < minw ? tw : minw, maxw = tw > maxw ? tw : maxw;
				minh = th < minh ? th : minh, maxh = th > maxh ? th : maxh;
				for (int y = r.y0; y < r.y1; y++)
					for (int x = r.x0; x < r.x1; x++)
						hits[(size_t)y * w + x]++;
			}
			int bad = 0;
			for (size_t k = 0; k < (size_t)w * h; k++)
				bad += hits[k] != 1;
			CHECK(bad == 0, "%dx%d in %d tiles: %d pixels covered other than once", w, h, n, bad);
			CHECK(maxw - minw <= 1 && maxh - minh <= 1, "%dx%d in %d tiles: widths %d..%d heights %d..%d",
			      w, h, n, minw, maxw, minh, maxh);
		}
		free(hits);
	}
	exrfile_rect r;
	CHECK(merge_tile_rect(640, 480, 0, 4, &r) && r.x1 == 320 && r.y1 == 240, "4 tiles of 640x480 are quarters");
	CHECK(merge_tile_rect(640, 480, 6, 7, &r) && r.y0 == 0 && r.x1 == 640, "7 tiles of a wide frame are columns");
	CHECK(!merge_tile_rect(640, 480, 4, 4, &r), "tile 4/4 is refused");
	CHECK(!merge_tile_rect(640, 480, 0, 0, &r), "0 tiles are refused");
	CHECK(!merge_tile_rect(2, 2, 0, 5, &r), "5 tiles of 2x2 pixels are refused");
	return check_done("test_tiles");
}

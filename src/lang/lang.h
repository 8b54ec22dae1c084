/* lang.h - the scene language's entry point: reads a scene file (and its includes) and builds the
 * scene IR (scene/scene.h). Errors go to a diag object as `file:line:col: error: ...` with the
 * source line quoted; the parser stops at the first syntax or evaluation error, while IR validation
 * (scene_validate) reports every problem it finds. Not thread-safe per call; calls on different
 * diag/scene objects may run concurrently (there is no global state). */
#ifndef CIRCE_LANG_LANG_H
#define CIRCE_LANG_LANG_H

#include "base/diag.h"
#include "scene/pigment.h"
#include "scene/scene.h"

#include <stdbool.h>
#include <stddef.h>

/* Limits that keep hostile input harmless; each is stated in its error message. */
enum {
	LANG_MAX_INCLUDE_DEPTH = 64,
	LANG_MAX_DEPTH = 200, /* recursion: nested blocks, parentheses, unary operators, colours,
				 directives run inside others (#declare X = #while ...), #if/#while */
	LANG_MAX_LOOP_ITERATIONS = 1000000, /* per #while loop */
	LANG_MAX_MACRO_DEPTH = 100, /* macro calls running at once (recursion) */
	LANG_MAX_MACRO_PARAMS = 32, /* parameters of one #macro */
	LANG_MAX_VECTOR = 16, /* components of a vector literal (the matrix needs 12) */
};

/* image_width x image_height when the caller gives none: circe's default image (`circe render`). */
enum { LANG_DEFAULT_WIDTH = 640, LANG_DEFAULT_HEIGHT = 480 };

/* Reads the file at path (exactly as resolved by the parser) into a heap buffer obtained from
 * mem_alloc; the parser frees it with mem_free. Returns 0, or an errno value (ENOENT when the file
 * does not exist, which makes the parser try the next folder of the search path). */
typedef int (*lang_read_fn)(void *user, const char *path, char **text, size_t *len);

/* POV-Ray's trace(object, start, direction [, normal]): the nearest hit past org along dir on the
 * objects objs[0..n) of one object value (sc: the scene as parsed so far; key: the same pointer for
 * the same declared object, for the callee's cache). Returns 1 with *hit and the unit outward normal
 * *normal, 0 for no hit, -1 after reporting at loc. The language knows no meshes: main.c gives the
 * build's world_trace; without one, trace() is an error. */
typedef int (*lang_trace_fn)(void *user, const scene *sc, const scene_object *objs, size_t n, const void *key,
			     dvec3 org, dvec3 dir, dvec3 *hit, dvec3 *normal, diag *d, diag_loc loc);

/* POV-Ray's object pattern and inside(object, point): the inside of objs[0..n) as sc's function of
 * a point (1 inside, 0 outside), valid while the callee's state lives (main.c keeps it until the
 * scene is freed). False after reporting at loc. */
typedef bool (*lang_inside_fn)(void *user, const scene *sc, const scene_object *objs, size_t n, const void *key,
			       scene_fn *out, diag *d, diag_loc loc);

typedef struct lang_options {
	const char *const *include_dirs; /* the -I folders, searched after the including file's */
	size_t n_include_dirs;
	double clock; /* the value of `clock` (and of initial_clock and final_clock) */
	bool animated; /* a frame of an animation (--frame): `clock_on` is 1 and frame_number is frame */
	long frame; /* with animated: the frame number (and initial_frame and final_frame) */
	int width, height; /* image_width and image_height; 0: LANG_DEFAULT_WIDTH x LANG_DEFAULT_HEIGHT */
	lang_read_fn read; /* NULL: read from the file system */
	void *read_user;
	long max_loop_iterations; /* per #while (and 10x that in all); 0: LANG_MAX_LOOP_ITERATIONS and
				     10,000,000 in all. A fuzzer lowers it to keep inputs fast. */
	lang_trace_fn trace; /* NULL: trace() is refused with an error */
	lang_inside_fn inside; /* NULL: the object pattern and inside() are refused with an error */
	void *trace_user; /* both's */
} lang_options;

typedef enum lang_status {
	LANG_OK = 0,
	LANG_IO_ERROR, /* the scene file itself could not be read (exit 1) */
	LANG_SCENE_ERROR, /* syntax, evaluation or validation errors were reported (exit 3) */
	LANG_NO_MEMORY /* reported as a runtime error (exit 1) */
} lang_status;

/* Parses and validates the scene at path. On LANG_OK *out is a new scene the caller frees with
 * scene_free, its source_hash the FNV-1a (64-bit) of the text of every file read for it (the
 * scene and its includes, in the order read): tiles of one frame must agree on it. Otherwise
 * *out is NULL. opt may be NULL (defaults: no -I, clock 0, the disk). */
lang_status lang_parse_file(const char *path, const lang_options *opt, diag *d, scene **out);

/* The default file reader (the file system). */
int lang_read_file(void *user, const char *path, char **text, size_t *len);

#endif

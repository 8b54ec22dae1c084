/* assets.c - open, stat and read the head of every file a scene names. */
#include "build/assets.h"

#include "io/image.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *kind_name(scene_asset_kind k)
{
	static const char *names[] = {[SCENE_ASSET_IMAGE] = "image file", [SCENE_ASSET_MESH] = "mesh file",
				      [SCENE_ASSET_CAGE] = "cage file", [SCENE_ASSET_FONT] = "font file"};
	return names[k];
}

/* One asset: its file must open, be a regular file and, for an image, start like one. */
static bool open_one(const scene_asset *a, diag *d)
{
	const char *what = kind_name(a->kind);
	/* O_NONBLOCK: a FIFO without a writer must not hang the build; it is refused below. */
	int fd = open(a->path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
	if (fd < 0) {
		diag_error(d, a->loc, "%s '%s': cannot open it: %s", what, a->path, strerror(errno));
		return false;
	}
	struct stat st;
	unsigned char head[IMAGE_SIGNATURE_BYTES];
	ssize_t got = 0;
	bool ok = false;
	if (fstat(fd, &st) != 0)
		diag_error(d, a->loc, "%s '%s': cannot read it: %s", what, a->path, strerror(errno));
	else if (S_ISDIR(st.st_mode))
		diag_error(d, a->loc, "%s '%s': is a directory", what, a->path);
	else if (!S_ISREG(st.st_mode))
		diag_error(d, a->loc, "%s '%s': is not a regular file", what, a->path);
	else if ((got = read(fd, head, sizeof head)) < 0)
		diag_error(d, a->loc, "%s '%s': cannot read it: %s", what, a->path, strerror(errno));
	else if (a->kind == SCENE_ASSET_IMAGE && image_format_of(head, (size_t)got) == IMAGE_UNKNOWN)
		diag_error(d, a->loc, "%s '%s': not a PNG, JPEG, OpenEXR or Radiance HDR image", what, a->path);
	else
		ok = true;
	close(fd);
	return ok;
}

bool assets_open(const scene *sc, diag *d)
{
	const scene_asset *list = sc->assets.data;
	bool ok = true;
	for (size_t i = 0; i < sc->assets.len; i++)
		ok = open_one(&list[i], d) && ok;
	return ok;
}

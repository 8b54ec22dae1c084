/* exr.c - writing and reading OpenEXR through the C core's chunk encode/decode pipelines. */
#include "io/exr.h"

#include "base/mem.h"
#include "io/atomic.h"

#include <OpenEXR/openexr.h>

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* What the OpenEXR callbacks see: our file descriptor and a place for the library's last message. */
typedef struct exr_io {
	int fd;
	char msg[256];
} exr_io;

static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
	void *ud = NULL;
	if (exr_get_user_data(ctxt, &ud) == EXR_ERR_SUCCESS && ud)
		snprintf(((exr_io *)ud)->msg, sizeof ((exr_io *)ud)->msg, "%s (%s)", msg,
			 exr_get_default_error_message(code));
}

static int64_t write_fd(exr_const_context_t ctxt, void *ud, const void *buf, uint64_t sz,
			uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
	exr_io *io = ud;
	const char *p = buf;
	uint64_t done = 0;
	while (done < sz) {
		ssize_t n = pwrite(io->fd, p + done, sz - done, (off_t)(offset + done));
		if (n < 0) {
			if (errno == EINTR)
				continue;
			error_cb(ctxt, EXR_ERR_WRITE_IO, "%s", strerror(errno));
			return -1;
		}
		done += (uint64_t)n;
	}
	return (int64_t)done;
}

static const char *exr_reason(const exr_io *io, exr_result_t rv)
{
	return io->msg[0] ? io->msg : exr_get_default_error_message(rv);
}

static bool rect_ok(exrfile_rect r) { return r.x1 > r.x0 && r.y1 > r.y0; }

/* Sets one header attribute. */
static exr_result_t put_attr(exr_context_t ctx, const exrfile_attr *a)
{
	switch (a->kind) {
	case EXRFILE_ATTR_STRING:
		return exr_attr_set_string(ctx, 0, a->name, a->s ? a->s : "");
	case EXRFILE_ATTR_INT:
		return exr_attr_set_int(ctx, 0, a->name, a->i);
	case EXRFILE_ATTR_FLOAT:
		return exr_attr_set_float(ctx, 0, a->name, (float)a->d);
	case EXRFILE_ATTR_DOUBLE:
		return exr_attr_set_double(ctx, 0, a->name, a->d);
	case EXRFILE_ATTR_OTHER:
		break;
	}
	return EXR_ERR_INVALID_ARGUMENT;
}

/* Encodes every scanline chunk of part 0 from the caller's channel arrays. */
static exr_result_t write_chunks(exr_context_t ctx, const exrfile_write_desc *desc)
{
	int spc = 0;
	exr_result_t rv = exr_get_scanlines_per_chunk(ctx, 0, &spc);
	if (rv != EXR_ERR_SUCCESS)
		return rv;
	exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
	bool first = true;
	for (int y = desc->data.y0; y < desc->data.y1 && rv == EXR_ERR_SUCCESS; y += spc) {
		exr_chunk_info_t ci;
		rv = exr_write_scanline_chunk_info(ctx, 0, y, &ci);
		if (rv != EXR_ERR_SUCCESS)
			break;
		rv = first ? exr_encoding_initialize(ctx, 0, &ci, &enc) : exr_encoding_update(ctx, 0, &ci, &enc);
		if (rv != EXR_ERR_SUCCESS)
			break;
		int row = y - desc->data.y0;
		for (int c = 0; c < enc.channel_count; c++) {
			const exrfile_channel *ch = NULL;
			for (int k = 0; k < desc->nchannels; k++)
				if (!strcmp(desc->channels[k].name, enc.channels[c].channel_name))
					ch = &desc->channels[k];
			if (!ch)
				return EXR_ERR_INVALID_ARGUMENT;
			enc.channels[c].user_bytes_per_element = 4;
			enc.channels[c].user_data_type = EXR_PIXEL_FLOAT;
			enc.channels[c].user_pixel_stride = (int32_t)(ch->pixel_stride * sizeof(float));
			enc.channels[c].user_line_stride = (int32_t)(ch->row_stride * sizeof(float));
			enc.channels[c].encode_from_ptr = (const uint8_t *)(ch->data + (size_t)row * ch->row_stride);
		}
		if (first) {
			rv = exr_encoding_choose_default_routines(ctx, 0, &enc);
			first = false;
		}
		if (rv == EXR_ERR_SUCCESS)
			rv = exr_encoding_run(ctx, 0, &enc);
	}
	exr_encoding_destroy(ctx, &enc);
	return rv;
}

bool exrfile_write(const char *path, const exrfile_write_desc *desc, diag *d)
{
	const exrfile_rect *dw = &desc->data, *dp = &desc->display;
	if (!rect_ok(*dw) || !rect_ok(*dp) || desc->nchannels < 1 ||
	    (size_t)(dw->y1 - dw->y0) * (size_t)(dw->x1 - dw->x0) > (size_t)INT_MAX) {
		diag_file_error(d, path, "invalid image description for writing");
		return false;
	}
	atomic_file af;
	if (!atomic_open(&af, path, d))
		return false;
	exr_io io = {.fd = af.fd};
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	init.user_data = &io;
	init.write_fn = write_fd;
	init.error_handler_fn = on_error;
	exr_context_t ctx = NULL;
	exr_result_t rv = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
	int part = 0;
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_add_part(ctx, "", EXR_STORAGE_SCANLINE, &part);
	if (rv == EXR_ERR_SUCCESS) {
		exr_attr_box2i_t disp, data;
		disp.min.x = dp->x0, disp.min.y = dp->y0, disp.max.x = dp->x1 - 1, disp.max.y = dp->y1 - 1;
		data.min.x = dw->x0, data.min.y = dw->y0, data.max.x = dw->x1 - 1, data.max.y = dw->y1 - 1;
		exr_attr_v2f_t centre;
		centre.x = centre.y = 0.0f;
		rv = exr_initialize_required_attr(ctx, 0, &disp, &data, 1.0f, &centre, 1.0f,
						  EXR_LINEORDER_INCREASING_Y, EXR_COMPRESSION_ZIP);
	}
	for (int c = 0; c < desc->nchannels && rv == EXR_ERR_SUCCESS; c++)
		rv = exr_add_channel(ctx, 0, desc->channels[c].name, EXR_PIXEL_FLOAT,
				     EXR_PERCEPTUALLY_LINEAR, 1, 1);
	for (int a = 0; a < desc->nattrs && rv == EXR_ERR_SUCCESS; a++)
		rv = put_attr(ctx, &desc->attrs[a]);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_write_header(ctx);
	if (rv == EXR_ERR_SUCCESS)
		rv = write_chunks(ctx, desc);
	exr_result_t fin = ctx ? exr_finish(&ctx) : EXR_ERR_SUCCESS;
	if (rv == EXR_ERR_SUCCESS)
		rv = fin;
	if (rv != EXR_ERR_SUCCESS) {
		diag_file_error(d, path, "cannot write EXR: %s", exr_reason(&io, rv));
		atomic_abort(&af);
		return false;
	}
	return atomic_commit(&af, d);
}

void exrfile_free(exrfile_image *img)
{
	for (int c = 0; c < img->nchannels; c++) {
		mem_free(img->names ? img->names[c] : NULL);
		mem_free(img->planes ? img->planes[c] : NULL);
	}
	mem_free(img->names);
	mem_free(img->planes);
	for (int a = 0; a < img->nattrs; a++) {
		mem_free((char *)img->attrs[a].name);
		mem_free((char *)img->attrs[a].s);
	}
	mem_free(img->attrs);
	memset(img, 0, sizeof *img);
}

/* Copies the header attributes circe can print or interpret. */
static exr_result_t read_attrs(exr_context_t ctx, exrfile_image *img)
{
	int32_t count = 0;
	exr_result_t rv = exr_get_attribute_count(ctx, 0, &count);
	if (rv != EXR_ERR_SUCCESS)
		return rv;
	img->attrs = mem_calloc((size_t)count, sizeof *img->attrs);
	if (!img->attrs)
		return EXR_ERR_OUT_OF_MEMORY;
	for (int32_t i = 0; i < count; i++) {
		const exr_attribute_t *a = NULL;
		rv = exr_get_attribute_by_index(ctx, 0, EXR_ATTR_LIST_FILE_ORDER, i, &a);
		if (rv != EXR_ERR_SUCCESS)
			return rv;
		exrfile_attr *o = &img->attrs[img->nattrs++];
		o->name = mem_strdup(a->name);
		switch (a->type) {
		case EXR_ATTR_STRING:
			o->kind = EXRFILE_ATTR_STRING;
			o->s = mem_alloc((size_t)a->string->length + 1, 1);
			if (o->s) {
				memcpy((char *)o->s, a->string->str, (size_t)a->string->length);
				((char *)o->s)[a->string->length] = '\0';
			}
			break;
		case EXR_ATTR_INT:
			o->kind = EXRFILE_ATTR_INT;
			o->i = a->i;
			o->d = a->i;
			break;
		case EXR_ATTR_FLOAT:
			o->kind = EXRFILE_ATTR_FLOAT;
			o->d = a->f;
			break;
		case EXR_ATTR_DOUBLE:
			o->kind = EXRFILE_ATTR_DOUBLE;
			o->d = a->d;
			break;
		default:
			o->kind = EXRFILE_ATTR_OTHER;
			o->s = mem_strdup(a->type_name);
			break;
		}
		if (!o->name || ((o->kind == EXRFILE_ATTR_STRING || o->kind == EXRFILE_ATTR_OTHER) && !o->s))
			return EXR_ERR_OUT_OF_MEMORY;
	}
	return EXR_ERR_SUCCESS;
}

/* Decodes one chunk into the planes at its place in the data window. */
static exr_result_t decode_chunk(exr_context_t ctx, exrfile_image *img, const exr_chunk_info_t *ci,
				 exr_decode_pipeline_t *dec, bool *first, int x, int y)
{
	exr_result_t rv = *first ? exr_decoding_initialize(ctx, 0, ci, dec) : exr_decoding_update(ctx, 0, ci, dec);
	if (rv != EXR_ERR_SUCCESS)
		return rv;
	for (int c = 0; c < dec->channel_count; c++) {
		int k = 0;
		while (k < img->nchannels && strcmp(img->names[k], dec->channels[c].channel_name))
			k++;
		if (k == img->nchannels || dec->channels[c].x_samples != 1 || dec->channels[c].y_samples != 1)
			return EXR_ERR_FEATURE_NOT_IMPLEMENTED;
		dec->channels[c].user_bytes_per_element = 4;
		dec->channels[c].user_data_type = EXR_PIXEL_FLOAT;
		dec->channels[c].user_pixel_stride = 4;
		dec->channels[c].user_line_stride = (int32_t)(img->width * 4);
		dec->channels[c].decode_to_ptr =
			(uint8_t *)(img->planes[k] + (size_t)(y - img->data.y0) * img->width + (x - img->data.x0));
	}
	if (*first) {
		rv = exr_decoding_choose_default_routines(ctx, 0, dec);
		*first = false;
	}
	return rv == EXR_ERR_SUCCESS ? exr_decoding_run(ctx, 0, dec) : rv;
}

static exr_result_t read_pixels(exr_context_t ctx, exrfile_image *img)
{
	exr_storage_t storage;
	exr_result_t rv = exr_get_storage(ctx, 0, &storage);
	if (rv != EXR_ERR_SUCCESS)
		return rv;
	exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
	bool first = true;
	if (storage == EXR_STORAGE_SCANLINE) {
		int spc = 0;
		rv = exr_get_scanlines_per_chunk(ctx, 0, &spc);
		for (int y = img->data.y0; y < img->data.y1 && rv == EXR_ERR_SUCCESS; y += spc) {
			exr_chunk_info_t ci;
			rv = exr_read_scanline_chunk_info(ctx, 0, y, &ci);
			if (rv == EXR_ERR_SUCCESS)
				rv = decode_chunk(ctx, img, &ci, &dec, &first, img->data.x0, ci.start_y);
		}
	} else if (storage == EXR_STORAGE_TILED) {
		int32_t tw = 0, th = 0;
		int32_t lw = 0, lh = 0;
		rv = exr_get_tile_sizes(ctx, 0, 0, 0, &tw, &th);
		if (rv == EXR_ERR_SUCCESS)
			rv = exr_get_level_sizes(ctx, 0, 0, 0, &lw, &lh);
		if (rv == EXR_ERR_SUCCESS && (tw <= 0 || th <= 0))
			rv = EXR_ERR_INVALID_ATTR;
		int ntx = rv ? 0 : (lw + tw - 1) / tw, nty = rv ? 0 : (lh + th - 1) / th;
		for (int ty = 0; ty < nty && rv == EXR_ERR_SUCCESS; ty++)
			for (int tx = 0; tx < ntx && rv == EXR_ERR_SUCCESS; tx++) {
				exr_chunk_info_t ci;
				rv = exr_read_tile_chunk_info(ctx, 0, tx, ty, 0, 0, &ci);
				if (rv == EXR_ERR_SUCCESS)
					rv = decode_chunk(ctx, img, &ci, &dec, &first, img->data.x0 + tx * tw,
							  img->data.y0 + ty * th);
			}
	} else {
		rv = EXR_ERR_FEATURE_NOT_IMPLEMENTED; /* deep images */
	}
	exr_decoding_destroy(ctx, &dec);
	return rv;
}

bool exrfile_read(const char *path, exrfile_image *img, diag *d)
{
	memset(img, 0, sizeof *img);
	exr_io io = {.fd = -1};
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	init.user_data = &io;
	init.error_handler_fn = on_error;
	init.flags = EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
	exr_context_t ctx = NULL;
	exr_result_t rv = exr_start_read(&ctx, path, &init);
	exr_attr_box2i_t dw, dp;
	memset(&dw, 0, sizeof dw);
	memset(&dp, 0, sizeof dp);
	const exr_attr_chlist_t *chl = NULL;
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_data_window(ctx, 0, &dw);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_display_window(ctx, 0, &dp);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_channels(ctx, 0, &chl);
	if (rv == EXR_ERR_SUCCESS) {
		img->data = (exrfile_rect){dw.min.x, dw.min.y, dw.max.x + 1, dw.max.y + 1};
		img->display = (exrfile_rect){dp.min.x, dp.min.y, dp.max.x + 1, dp.max.y + 1};
		img->width = img->data.x1 - img->data.x0;
		img->height = img->data.y1 - img->data.y0;
		size_t npix, nsamples;
		if (img->width <= 0 || img->height <= 0 ||
		    !mem_mul_ok((size_t)img->width, (size_t)img->height, &npix)) {
			rv = EXR_ERR_BAD_CHUNK_LEADER;
		} else if (!mem_mul_ok(npix, (size_t)chl->num_channels, &nsamples) ||
			   nsamples > EXRFILE_MAX_SAMPLES) {
			/* Checked before any plane is allocated: a corrupt or hostile header must not
			 * make circe reserve what the file cannot hold. */
			snprintf(io.msg, sizeof io.msg,
				 "its data window (%d x %d pixels, %d channel%s) holds more samples than circe "
				 "reads (limit %llu)",
				 img->width, img->height, chl->num_channels, chl->num_channels == 1 ? "" : "s",
				 (unsigned long long)EXRFILE_MAX_SAMPLES);
			rv = EXR_ERR_OUT_OF_MEMORY;
		}
	}
	if (rv == EXR_ERR_SUCCESS) {
		img->names = mem_calloc((size_t)chl->num_channels, sizeof(char *));
		img->planes = mem_calloc((size_t)chl->num_channels, sizeof(float *));
		if (!img->names || !img->planes)
			rv = EXR_ERR_OUT_OF_MEMORY;
		for (int c = 0; c < chl->num_channels && rv == EXR_ERR_SUCCESS; c++) {
			img->nchannels++;
			img->names[c] = mem_strdup(chl->entries[c].name.str);
			img->planes[c] = mem_calloc((size_t)img->width * (size_t)img->height, sizeof(float));
			if (!img->names[c] || !img->planes[c])
				rv = EXR_ERR_OUT_OF_MEMORY;
		}
	}
	if (rv == EXR_ERR_SUCCESS)
		rv = read_attrs(ctx, img);
	if (rv == EXR_ERR_SUCCESS)
		rv = read_pixels(ctx, img);
	if (ctx)
		exr_finish(&ctx);
	if (rv != EXR_ERR_SUCCESS) {
		diag_file_error(d, path, "cannot read EXR: %s", exr_reason(&io, rv));
		exrfile_free(img);
		return false;
	}
	return true;
}

const float *exrfile_find_channel(const exrfile_image *img, const char *name)
{
	for (int c = 0; c < img->nchannels; c++)
		if (!strcmp(img->names[c], name))
			return img->planes[c];
	return NULL;
}

const exrfile_attr *exrfile_attr_find(const exrfile_image *img, const char *name)
{
	for (int a = 0; a < img->nattrs; a++)
		if (!strcmp(img->attrs[a].name, name))
			return &img->attrs[a];
	return NULL;
}

bool exrfile_attr_is_structural(const char *name)
{
	static const char *const names[] = {
		"channels",   "compression",        "dataWindow",        "displayWindow", "lineOrder",
		"pixelAspectRatio", "screenWindowCenter", "screenWindowWidth", "tiles", "type",
		"name",       "version",            "chunkCount",
	};
	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
		if (!strcmp(name, names[i]))
			return true;
	return false;
}

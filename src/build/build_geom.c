/* build_geom.c - the scene's geometry records tessellated: boxes, meshes, mesh files and
 * subdivision surfaces (spheres and planes are made per object, in build_inst.c). */
#include "build/build_impl.h"

#include "base/mem.h"
#include "geom/cage.h"
#include "geom/prim.h"
#include "geom/subdiv.h"

#include <string.h>

/* The subdivision options of a cage: uniform level, or adaptive through the scene's camera. */
static subd_options subdiv_options(const scene *sc, const scene_subdiv *sd, const world_options *opt,
				   subd_camera *camera)
{
	subd_options so = {.level = sd->level, .max_bytes = opt->max_memory};
	if (sd->level <= 0 && sd->max_edge_px > 0) {
		*camera = scene_view(sc, opt);
		so.camera = camera;
		so.max_edge_px = (float)sd->max_edge_px;
	}
	return so;
}

/* The creases and corners of a cage: a file's tags first, then the scene's, so that where both
 * name an edge the scene's sharpness holds (subd_tessellate keeps the later one). The scene's
 * indices are the file's own vertex numbers, mapped through its welding; each is checked against
 * the cage (a file cage is only known here) and reported at the scene's place. */
static bool subdiv_tags(const scene_subdiv *sd, const cage_data *file, subd_cage *cage, diag *d)
{
	uint32_t fc = file ? file->num_creases : 0, fk = file ? file->num_corners : 0;
	size_t nc = (size_t)fc + sd->n_creases, nk = (size_t)fk + sd->n_corners;
	uint32_t *crease_v = mem_alloc(2 * nc, sizeof *crease_v), *corner_v = mem_alloc(nk, sizeof *corner_v);
	float *crease_s = mem_alloc(nc, sizeof *crease_s), *corner_s = mem_alloc(nk, sizeof *corner_s);
	if (!crease_v || !crease_s || !corner_v || !corner_s) {
		mem_free(crease_v), mem_free(crease_s), mem_free(corner_v), mem_free(corner_s);
		diag_error(d, sd->file ? sd->file_loc : diag_noloc(), "out of memory");
		return false;
	}
	if (file) {
		memcpy(crease_v, file->crease_vertices, 2 * (size_t)fc * sizeof *crease_v);
		memcpy(crease_s, file->crease_sharpness, fc * sizeof *crease_s);
		memcpy(corner_v, file->corner_vertices, fk * sizeof *corner_v);
		memcpy(corner_s, file->corner_sharpness, fk * sizeof *corner_s);
	}
	int errors = 0;
	for (uint32_t i = 0; i < sd->n_creases; i++) {
		const scene_crease *c = &sd->creases[i];
		uint32_t a = c->a, b = c->b;
		if (file && (a >= file->num_file_vertices || b >= file->num_file_vertices)) {
			diag_error(d, c->loc, "crease %u: vertex %u is out of range (the cage file '%s' has %u vertices)", i,
				   a >= file->num_file_vertices ? a : b, sd->file, file->num_file_vertices);
			errors++;
			continue;
		}
		if (file) {
			a = file->weld[a], b = file->weld[b];
			if (!cage_has_edge(file, a, b)) {
				diag_error(d, c->loc, "crease %u: <%u, %u> is not an edge of the cage in '%s'", i, c->a, c->b,
					   sd->file);
				errors++;
				continue;
			}
		}
		crease_v[2 * (fc + i)] = a, crease_v[2 * (fc + i) + 1] = b;
		crease_s[fc + i] = c->sharpness;
	}
	for (uint32_t i = 0; i < sd->n_corners; i++) {
		const scene_corner *c = &sd->corners[i];
		uint32_t v = c->vertex;
		if (file && v >= file->num_file_vertices) {
			diag_error(d, c->loc, "corner %u: vertex %u is out of range (the cage file '%s' has %u vertices)", i,
				   v, sd->file, file->num_file_vertices);
			errors++;
			continue;
		}
		corner_v[fk + i] = file ? file->weld[v] : v;
		corner_s[fk + i] = c->sharpness;
	}
	if (errors) {
		mem_free(crease_v), mem_free(crease_s), mem_free(corner_v), mem_free(corner_s);
		return false;
	}
	cage->crease_vertices = crease_v, cage->crease_sharpness = crease_s, cage->num_creases = (uint32_t)nc;
	cage->corner_vertices = corner_v, cage->corner_sharpness = corner_s, cage->num_corners = (uint32_t)nk;
	return true;
}

static bool build_subdiv(world *w, const scene *sc, const scene_geom *g, const world_options *opt, mesh *m,
			 diag *d)
{
	const scene_subdiv *sd = &g->u.subdiv;
	cage_data file;
	subd_cage cage;
	if (sd->file) {
		if (!cage_load(sd->file, &file, d, sd->file_loc))
			return false;
		w->stats.cage_file_faces += file.num_faces;
		cage = cage_view(&file);
		cage.source = sd->file;
	} else {
		cage = (subd_cage){
			.positions = sd->vertices, .num_vertices = sd->n_vertices,
			.face_sizes = sd->face_sizes, .num_faces = sd->n_faces, .face_indices = sd->face_verts,
			.uvs = sd->n_uv_faces ? sd->uvs : NULL, .num_uvs = sd->n_uvs,
			.uv_indices = sd->n_uv_faces ? sd->uv_face_verts : NULL,
		};
	}
	cage.scheme = sd->scheme == SCENE_SUBD_LOOP ? SUBD_LOOP : SUBD_CATMULL_CLARK;
	/* The scene's boundary rule when written, else the file's tag, else the language's default. */
	cage.boundary = sd->file && !sd->boundary_given && file.has_boundary ? file.boundary
		      : sd->boundary == SCENE_SUBD_EDGE_AND_CORNER ? SUBD_BOUNDARY_EDGE_AND_CORNER
								   : SUBD_BOUNDARY_EDGE_ONLY;
	bool ok = subdiv_tags(sd, sd->file ? &file : NULL, &cage, d);
	if (ok) {
		subd_camera camera;
		subd_options so = subdiv_options(sc, sd, opt, &camera);
		ok = subd_tessellate(&cage, &so, m, d, sd->file ? sd->file_loc : g->loc);
		mem_free((void *)cage.crease_vertices), mem_free((void *)cage.crease_sharpness);
		mem_free((void *)cage.corner_vertices), mem_free((void *)cage.corner_sharpness);
	}
	if (sd->file)
		cage_free(&file);
	return ok;
}

/* Tessellates one geometry record (spheres and planes wait for their objects' transforms). */
bool build_geom(world *w, const scene *sc, const scene_geom *g, const world_options *opt, diag *d)
{
	mesh *m = &w->geoms[g->id].m;
	switch (g->kind) {
	case SHAPE_SPHERE: /* an instance of a unit sphere, chosen per object (sphere_instance) */
		return true;
	case SHAPE_BOX:
		if (!prim_box(d3v(g->u.box.corner1), d3v(g->u.box.corner2), m))
			break;
		return true;
	case SHAPE_PLANE:
		return true;
	case SHAPE_MESH: {
		const scene_mesh *sm = &g->u.mesh;
		mesh_arrays a = {sm->positions, sm->n_positions, sm->normals, sm->n_normals, sm->uvs, sm->n_uvs,
				 sm->faces, sm->normal_idx, sm->uv_idx, sm->n_faces};
		return mesh_from_arrays(&a, m, d, g->loc);
	}
	case SHAPE_MESH_FILE: {
		bool ok = mesh_import(g->u.file.path, m, d);
		if (!ok)
			diag_note(d, g->loc, "the mesh file was named here");
		return ok;
	}
	case SHAPE_SUBDIV:
		w->stats.subdiv_surfaces++;
		return build_subdiv(w, sc, g, opt, m, d);
	case SHAPE_POV:
		return build_pov_shape(w, sc, g, opt, d);
	case SHAPE_CONE: case SHAPE_TORUS: case SHAPE_DISC: case SHAPE_POLYGON: case SHAPE_SUPERELLIPSOID:
	case SHAPE_HEIGHT_FIELD: case SHAPE_QUADRIC: case SHAPE_POLY:
		return true; /* made for the objects that use them (build_shapes.c) */
	}
	diag_error(d, g->loc, "out of memory while tessellating");
	return false;
}

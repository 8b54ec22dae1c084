/* scene.c - IR lifetime, validation, statistics and the text dump used by golden tests. */
#include "scene/scene.h"

#include "geom/shape.h"
#include "scene/pigment.h"

#include <math.h>
#include <string.h>

scene *scene_new(void)
{
	scene *s = mem_calloc(1, sizeof *s);
	if (!s)
		return NULL;
	arena_init(&s->arena, 64 * 1024);
	vecbuf_init(&s->lights, sizeof(scene_light));
	vecbuf_init(&s->light_groups, sizeof(scene_light_group));
	vecbuf_init(&s->objects, sizeof(scene_object));
	vecbuf_init(&s->assets, sizeof(scene_asset));
	vecbuf_init(&s->clamped_colors, sizeof(diag_loc));
	s->global.mm_per_unit = 10.0;
	s->global.max_trace_level = 5;
	s->global.assumed_gamma = 1.0;
	s->global.working_gamma = 1.0;
	s->global.ambient_light = v3s(1.0f);
	s->global.subsurface_samples[0] = s->global.subsurface_samples[1] = 50; /* POV-Ray 3.7 scenedata.cpp */
	return s;
}

static void free_geom_arrays(scene_geom *g)
{
	if (g->kind == SHAPE_MESH) {
		scene_mesh *m = &g->u.mesh;
		mem_free(m->positions), mem_free(m->normals), mem_free(m->uvs);
		mem_free(m->faces), mem_free(m->normal_idx), mem_free(m->uv_idx);
	} else if (g->kind == SHAPE_SUBDIV) {
		scene_subdiv *d = &g->u.subdiv;
		mem_free(d->vertices), mem_free(d->face_sizes), mem_free(d->face_verts);
		mem_free(d->face_locs), mem_free(d->uvs), mem_free(d->uv_face_sizes);
		mem_free(d->uv_face_verts), mem_free(d->creases), mem_free(d->corners);
	}
}

void scene_free(scene *s)
{
	if (!s)
		return;
	for (scene_geom *g = s->geoms; g; g = g->next)
		free_geom_arrays(g);
	vecbuf_free(&s->lights);
	vecbuf_free(&s->light_groups);
	vecbuf_free(&s->objects);
	vecbuf_free(&s->assets);
	vecbuf_free(&s->clamped_colors);
	arena_release(&s->arena);
	mem_free(s);
}

static bool same_loc(diag_loc a, diag_loc b) { return a.src == b.src && a.line == b.line && a.col == b.col; }

bool scene_color_finalise(scene *s, diag *d, diag_loc loc, const char *what, scene_color_use use, vec3 *c)
{
	vec3 given = *c;
	if (!scene_color_clamp(c, use))
		return true;
	for (size_t i = 0; i < s->clamped_colors.len; i++)
		if (same_loc(VECBUF_AT(&s->clamped_colors, diag_loc, i), loc))
			return true;
	if (!vecbuf_push(&s->clamped_colors, &loc)) {
		diag_error(d, loc, "out of memory");
		return false;
	}
	diag_warning(d, loc, "%s <%g, %g, %g> is outside %s, the range of a %s: clamped to <%g, %g, %g>", what,
		     (double)given.x, (double)given.y, (double)given.z, scene_color_range_name(use),
		     use == SCENE_COLOR_REFLECTANCE ? "reflectance" : "radiance", (double)c->x, (double)c->y,
		     (double)c->z);
	return true;
}

scene_geom *scene_new_geom(scene *s, scene_shape_kind kind, diag_loc loc)
{
	scene_geom *g = arena_zalloc(&s->arena, 1, sizeof *g);
	if (!g)
		return NULL;
	g->kind = kind;
	g->loc = loc;
	g->id = s->n_geoms++;
	g->next = s->geoms;
	s->geoms = g;
	if (kind == SHAPE_SUBDIV)
		g->u.subdiv.max_edge_px = 1.5; /* LANGUAGE.md default */
	return g;
}

scene_material *scene_new_material(scene *s, diag_loc loc)
{
	scene_material *m = arena_zalloc(&s->arena, 1, sizeof *m);
	if (!m)
		return NULL;
	m->loc = loc;
	m->id = s->n_materials++;
	m->color = v3s(0.8f);
	m->diffuse = 1.0f;
	m->roughness = 1.0f;
	scene_finish_defaults(&m->finish);
	m->next = s->materials;
	s->materials = m;
	return m;
}

bool scene_add_asset(scene *s, scene_asset_kind kind, const char *path, diag_loc loc)
{
	scene_asset a = {kind, path, loc};
	return vecbuf_push(&s->assets, &a) != NULL;
}

/* ---- validation ------------------------------------------------------------------------- */

/* Whether an object of s wears m (a declared texture no object uses is not warned about). */
static bool material_used(const scene *s, const scene_material *m)
{
	for (size_t i = 0; i < scene_n_objects(s); i++)
		if (scene_object_at(s, i)->material == m)
			return true;
	return false;
}

void scene_resolve_pov_sss(scene *s, diag *d)
{
	bool warned_off = false, warned_ior = false;
	for (scene_material *m = s->materials; m; m = m->next) {
		if (m->kind != MAT_TEXTURE || !m->finish.subsurface)
			continue;
		bool warn = (!warned_off || !warned_ior) && material_used(s, m);
		if (!s->global.subsurface) {
			if (warn && !warned_off)
				diag_warning(d, m->finish.subsurface_loc,
					     "the finish's subsurface renders as a plain diffuse finish: POV-Ray switches "
					     "it on with global_settings { subsurface { } } (said once per scene)");
			warned_off = warned_off || warn;
			continue;
		}
		m->pov_sss = true;
		memset(&m->sss, 0, sizeof m->sss);
		m->sss.profile = SSS_PROFILE_DIPOLE; /* POV-Ray's BSSRDF is Jensen et al. 2001's dipole */
		m->sss.method = SSS_METHOD_DEFAULT;
		m->sss.normal_strength = 1.0f;
		m->sss.ior = m->ior > 0.0f ? m->ior : 1.0f;
		if (!(m->ior > 0.0f) && warn && !warned_ior) {
			diag_warning(d, m->finish.subsurface_loc,
				     "a subsurface finish without interior { ior }: ior 1 as POV-Ray's (no boundary "
				     "refraction); give the object an interior (said once per scene)");
			warned_ior = true;
		}
	}
}

static int check_indices(diag *d, diag_loc loc, const char *what, const uint32_t *idx, uint32_t n_faces,
			 uint32_t n_items, const char *items)
{
	if (!idx)
		return 0;
	for (uint32_t f = 0; f < n_faces; f++)
		for (int k = 0; k < 3; k++)
			if (idx[3 * f + k] >= n_items) {
				diag_error(d, loc, "%s: face %u refers to %s %u, but there are only %u", what, f,
					   items, idx[3 * f + k], n_items);
				return 1;
			}
	return 0;
}

static int validate_mesh(const scene_geom *g, diag *d)
{
	const scene_mesh *m = &g->u.mesh;
	int e = 0;
	e += check_indices(d, g->loc, "mesh", m->faces, m->n_faces, m->n_positions, "vertex");
	e += check_indices(d, g->loc, "mesh", m->normal_idx, m->n_faces, m->n_normals, "normal");
	e += check_indices(d, g->loc, "mesh", m->uv_idx, m->n_faces, m->n_uvs, "uv");
	if (m->n_faces == 0) {
		diag_error(d, g->loc, "mesh has no triangles");
		e++;
	}
	return e;
}

/* True when a-b is an edge of some face of the cage. */
static bool cage_has_edge(const scene_subdiv *c, uint32_t a, uint32_t b)
{
	uint32_t base = 0;
	for (uint32_t f = 0; f < c->n_faces; f++) {
		uint32_t n = c->face_sizes[f];
		for (uint32_t k = 0; k < n; k++) {
			uint32_t u = c->face_verts[base + k], v = c->face_verts[base + (k + 1) % n];
			if ((u == a && v == b) || (u == b && v == a))
				return true;
		}
		base += n;
	}
	return false;
}

static int validate_subdiv(const scene_geom *g, diag *d)
{
	const scene_subdiv *c = &g->u.subdiv;
	int e = 0;
	if (c->file)
		return 0; /* the importer checks a file cage */
	uint32_t base = 0;
	for (uint32_t f = 0; f < c->n_faces; f++) {
		uint32_t n = c->face_sizes[f];
		if (n < 3) {
			diag_error(d, c->face_locs[f], "face %u has %u vertices; a face needs at least 3", f, n);
			e++;
		}
		if (c->scheme == SCENE_SUBD_LOOP && n != 3) {
			diag_error(d, c->face_locs[f], "face %u has %u vertices; the loop scheme needs triangles", f, n);
			e++;
		}
		for (uint32_t k = 0; k < n; k++)
			if (c->face_verts[base + k] >= c->n_vertices) {
				diag_error(d, c->face_locs[f], "face %u refers to vertex %u, but the cage has %u vertices",
					   f, c->face_verts[base + k], c->n_vertices);
				e++;
				break;
			}
		base += n;
	}
	if (c->uv_face_sizes) {
		if (c->n_uv_faces != c->n_faces) {
			diag_error(d, g->loc, "uv_faces has %u faces but the cage has %u", c->n_uv_faces, c->n_faces);
			e++;
		} else {
			uint32_t ub = 0;
			for (uint32_t f = 0; f < c->n_faces; f++) {
				if (c->uv_face_sizes[f] != c->face_sizes[f]) {
					diag_error(d, c->face_locs[f], "uv face %u has %u corners but face %u has %u", f,
						   c->uv_face_sizes[f], f, c->face_sizes[f]);
					e++;
				}
				for (uint32_t k = 0; k < c->uv_face_sizes[f]; k++)
					if (c->uv_face_verts[ub + k] >= c->n_uvs) {
						diag_error(d, c->face_locs[f], "uv face %u refers to uv %u, but there are only %u",
							   f, c->uv_face_verts[ub + k], c->n_uvs);
						e++;
						break;
					}
				ub += c->uv_face_sizes[f];
			}
		}
	}
	if (e)
		return e; /* edges of a broken cage mean nothing */
	for (uint32_t i = 0; i < c->n_creases; i++)
		if (!cage_has_edge(c, c->creases[i].a, c->creases[i].b)) {
			diag_error(d, c->creases[i].loc, "crease %u: <%u, %u> is not an edge of the cage", i,
				   c->creases[i].a, c->creases[i].b);
			e++;
		}
	for (uint32_t i = 0; i < c->n_corners; i++)
		if (c->corners[i].vertex >= c->n_vertices) {
			diag_error(d, c->corners[i].loc, "corner %u: vertex %u is out of range (the cage has %u vertices)",
				   i, c->corners[i].vertex, c->n_vertices);
			e++;
		}
	return e;
}

static int validate_camera(const scene_camera *c, diag *d)
{
	/* POV-Ray's handedness, the sign of (up x direction) . right (Parse_Camera), must exist:
	 * a zero or coplanar right, up, direction is degenerate with or without look_at. */
	double rl = d3_length(c->right), ul = d3_length(c->up), dl = d3_length(c->direction);
	/* With look_at only their lengths and the handedness's sign count (Parse_Camera re-aims
	 * them): up parallel to direction is POV-Ray's handedness 0, a mirrored camera. */
	if (!(rl > 0 && ul > 0 && dl > 0) ||
	    (!c->has_look_at && !(fabs(d3_dot(d3_cross(c->up, c->direction), c->right)) > 1e-9 * rl * ul * dl))) {
		diag_error(d, c->loc, "degenerate camera: right, up and direction do not span space (one is zero, or "
				      "two are parallel)");
		return 1;
	}
	if (!c->has_look_at)
		return 0; /* the frame is direction, right, up */
	dvec3 dir = d3_sub(c->look_at, c->location);
	double len = d3_length(dir);
	if (!(len > 0)) {
		diag_error(d, c->loc, "degenerate camera: look_at is the same point as location");
		return 1;
	}
	double sl = d3_length(c->sky);
	if (!(sl > 0)) {
		diag_error(d, c->loc, "degenerate camera: sky is the zero vector");
		return 1;
	}
	if (d3_length(d3_cross(d3_scale(dir, 1 / len), d3_scale(c->sky, 1 / sl))) < 1e-9) {
		/* POV-Ray warns and takes the right vector (given or its default x) instead of sky x
		 * direction */
		dvec3 r = c->has_right ? c->right : d3(1, 0, 0);
		if (d3_length(d3_cross(d3_scale(dir, 1 / len), r)) < 1e-9 * d3_length(r)) {
			diag_error(d, c->loc, "degenerate camera: sky and right are both parallel to the view direction");
			return 1;
		}
		diag_warning(d, c->loc, "camera: sky is parallel to the view direction; the right vector is used instead "
					"(as POV-Ray does)");
	}
	if (c->type == 0 && !(c->angle_deg > 0 && c->angle_deg < 180)) {
		diag_error(d, c->loc, "camera angle %g is outside (0, 180) degrees", c->angle_deg);
		return 1;
	}
	return 0;
}

int scene_validate(const scene *s, diag *d)
{
	int e = 0;
	if (s->has_camera)
		e += validate_camera(&s->camera, d);
	for (scene_geom *g = s->geoms; g; g = g->next) {
		if (g->kind == SHAPE_MESH)
			e += validate_mesh(g, d);
		else if (g->kind == SHAPE_SUBDIV)
			e += validate_subdiv(g, d);
	}
	return e;
}

/* ---- statistics -------------------------------------------------------------------------- */

static size_t geom_bytes(const scene_geom *g)
{
	if (g->kind == SHAPE_MESH) {
		const scene_mesh *m = &g->u.mesh;
		return m->n_positions * sizeof(vec3) + m->n_normals * sizeof(vec3) + m->n_uvs * sizeof(vec2) +
		       (size_t)m->n_faces * 3 * sizeof(uint32_t) * (1 + !!m->normal_idx + !!m->uv_idx);
	}
	if (g->kind == SHAPE_SUBDIV) {
		const scene_subdiv *c = &g->u.subdiv;
		return c->n_vertices * sizeof(vec3) + c->n_faces * (sizeof(uint32_t) + sizeof(diag_loc)) +
		       c->n_face_verts * sizeof(uint32_t) + c->n_uvs * sizeof(vec2) +
		       (c->n_uv_faces + c->n_uv_face_verts) * sizeof(uint32_t) +
		       c->n_creases * sizeof(scene_crease) + c->n_corners * sizeof(scene_corner);
	}
	return 0;
}

void scene_stats_get(const scene *s, scene_stats *st)
{
	memset(st, 0, sizeof *st);
	st->objects = scene_n_objects(s);
	st->lights = scene_n_lights(s);
	st->geoms = s->n_geoms;
	for (size_t i = 0; i < st->objects; i++) {
		const scene_object *o = scene_object_at(s, i);
		double scale;
		st->instances += o->instance;
		if (o->material && o->material->kind >= MAT_SKIN && !xform_is_similarity(&o->transform, &scale))
			st->sss_nonuniform++;
	}
	for (const scene_material *m = s->materials; m; m = m->next)
		st->materials_by_kind[m->kind]++;
	st->memory_bytes = sizeof *s + s->arena.total + s->objects.cap * s->objects.elem +
			   s->lights.cap * s->lights.elem;
	for (const scene_geom *g = s->geoms; g; g = g->next) {
		st->memory_bytes += geom_bytes(g);
		if (g->kind == SHAPE_MESH)
			st->mesh_triangles += g->u.mesh.n_faces;
		if (g->kind == SHAPE_SUBDIV)
			st->subdiv_faces += g->u.subdiv.n_faces;
	}
}

/* ---- dump ------------------------------------------------------------------------------- */

static void dump_v3(FILE *o, const char *name, vec3 v) { fprintf(o, " %s <%g, %g, %g>", name, v.x, v.y, v.z); }
static void dump_d3(FILE *o, const char *name, dvec3 v) { fprintf(o, " %s <%g, %g, %g>", name, v.x, v.y, v.z); }
/* The file's base name only: dumps must not depend on where the tree lives. */
/* The POV-Ray object flags, only those said: " hollow", " hollow off", " no_image", ... */
static void dump_pov_flags(FILE *o, uint8_t f)
{
	if (f & SCENE_OBJ_HOLLOW_SET)
		fprintf(o, (f & SCENE_OBJ_HOLLOW) ? " hollow" : " hollow off");
	if (f & SCENE_OBJ_NO_IMAGE)
		fprintf(o, " no_image");
	if (f & SCENE_OBJ_NO_REFLECTION)
		fprintf(o, " no_reflection");
	if (f & SCENE_OBJ_NO_RADIOSITY)
		fprintf(o, " no_radiosity");
	if (f & SCENE_OBJ_DOUBLE_ILLUMINATE)
		fprintf(o, " double_illuminate");
}

static void dump_loc(FILE *o, diag_loc l)
{
	const char *name = l.src ? l.src->name : "?";
	const char *slash = strrchr(name, '/');
	fprintf(o, " @%s:%u:%u", slash ? slash + 1 : name, l.line, l.col);
}

/* The POV-Ray finish items that differ from POV-Ray's defaults, on one line (none: no line). */
static void dump_finish(FILE *o, const scene_finish *f)
{
	if (scene_finish_is_default(f))
		return;
	fprintf(o, " ");
	if (f->has_ambient)
		dump_v3(o, "ambient", f->ambient);
	if (f->emission.x != 0 || f->emission.y != 0 || f->emission.z != 0)
		dump_v3(o, "emission", f->emission);
	fprintf(o, " brilliance %g phong %g phong_size %g metallic %g", f->brilliance, f->phong, f->phong_size,
		f->metallic);
	dump_v3(o, "reflection_min", f->refl_min);
	dump_v3(o, "reflection_max", f->refl_max);
	fprintf(o, " falloff %g fresnel %d reflection_metallic %g conserve_energy %d", f->refl_falloff,
		f->refl_fresnel, f->refl_metallic, f->conserve_energy);
	if (f->subsurface)
		dump_v3(o, "subsurface translucency", f->translucency_mm);
	fputc('\n', o);
}

/* A material's (or the atmosphere's) media, on its line. */
static void dump_media(FILE *o, const scene_material *m)
{
	for (uint32_t k = 0; k < m->n_media; k++) {
		const scene_media *md = &m->media[k];
		fprintf(o, " media");
		dump_v3(o, "absorption", md->absorption);
		dump_v3(o, "emission", md->emission);
		dump_v3(o, "scattering", md->scattering);
		fprintf(o, " type %d eccentricity %g extinction %g method %d densities %u", md->scattering_type,
			md->eccentricity, md->extinction, md->method, md->n_density);
		for (uint32_t j = 0; j < md->n_density; j++) {
			fprintf(o, " [");
			scene_pigment_dump(o, md->density[j]);
			fprintf(o, "]");
		}
	}
}

static void dump_material(FILE *o, const scene_material *m)
{
	fprintf(o, "material %u %s", m->id, scene_material_kind_name(m->kind));
	if (m->name)
		fprintf(o, " name %s", m->name);
	dump_loc(o, m->loc);
	fputc('\n', o);
	if (m->kind == MAT_DIFFUSE || m->kind == MAT_TEXTURE) {
		fprintf(o, " ");
		dump_v3(o, "color", m->color);
		if (m->image)
			fprintf(o, " image \"%s\"", m->image);
		fprintf(o, " diffuse %g specular %g roughness %g", m->diffuse, m->specular, m->roughness);
		if (m->filter > 0 || m->transmit > 0)
			fprintf(o, " filter %g transmit %g", m->filter, m->transmit);
		if (m->ior > 0)
			fprintf(o, " ior %g", m->ior);
		if (m->fade_distance > 0 || m->fade_power > 0) {
			fprintf(o, " fade_distance %g fade_power %g", m->fade_distance, m->fade_power);
			dump_v3(o, "fade_color", m->fade_color);
		}
		dump_media(o, m);
		fputc('\n', o);
		if (m->kind == MAT_TEXTURE)
			dump_finish(o, &m->finish);
		if (m->pov_sss)
			fprintf(o, "  pov_sss ior %g profile %s\n", m->sss.ior, sss_profile_name(m->sss.profile));
	}
	const struct scene_pigment *pg = m->kind >= MAT_SKIN && m->sss.pigment ? m->sss.pigment : m->pigment;
	if (pg) {
		fprintf(o, "  ");
		scene_pigment_dump(o, pg);
		fputc('\n', o);
	}
	if (m->normal) {
		fprintf(o, "  ");
		scene_pigment_dump(o, m->normal);
		fputc('\n', o);
	}
	if (m->emission.x != 0 || m->emission.y != 0 || m->emission.z != 0) {
		fprintf(o, " ");
		dump_v3(o, "emission", m->emission);
		fputc('\n', o);
	}
	if (m->kind >= MAT_SKIN) {
		const scene_sss *s = &m->sss;
		static const char *const forms[] = {"default", "physical", "artist"};
		const sss_medium_spec *md = &s->medium;
		fprintf(o, "  form %s", forms[md->form]);
		if (md->preset)
			fprintf(o, " preset %s", md->preset);
		fputc('\n', o);
		/* The parameters as written (or the block's defaults); the build derives the others. */
		if (md->has) {
			fprintf(o, " ");
			if (md->has & SSS_HAS_SIGMA_S)
				dump_v3(o, "sigma_s", md->sigma_s_per_mm);
			if (md->has & SSS_HAS_SIGMA_A)
				dump_v3(o, "sigma_a", md->sigma_a_per_mm);
			if (md->has & SSS_HAS_ALBEDO)
				dump_v3(o, "albedo", md->albedo);
			if (md->has & SSS_HAS_RADIUS)
				dump_v3(o, "radius", md->radius_mm);
			fputc('\n', o);
		}
		fprintf(o, "  ior %g roughness %g anisotropy %g profile %s method %s", s->ior, s->roughness,
			s->anisotropy, sss_profile_name(s->profile), sss_method_name(s->method));
		if (s->albedo_image)
			fprintf(o, " image \"%s\"", s->albedo_image);
		if (s->normal_map)
			fprintf(o, " normal_map \"%s\" strength %g", s->normal_map, s->normal_strength);
		if (s->group)
			fprintf(o, " group \"%s\"", s->group);
		fputc('\n', o);
	}
}

static void dump_geom(FILE *o, const scene_geom *g)
{
	fprintf(o, "geom %u %s", g->id, scene_shape_name(g));
	dump_loc(o, g->loc);
	switch (g->kind) {
	case SHAPE_SPHERE:
		dump_d3(o, "center", g->u.sphere.center);
		fprintf(o, " radius %g\n", g->u.sphere.radius);
		break;
	case SHAPE_BOX:
		dump_d3(o, "corner1", g->u.box.corner1);
		dump_d3(o, "corner2", g->u.box.corner2);
		fputc('\n', o);
		break;
	case SHAPE_PLANE:
		dump_d3(o, "normal", g->u.plane.normal);
		fprintf(o, " offset %g\n", g->u.plane.offset);
		break;
	case SHAPE_MESH_FILE:
		fprintf(o, " file \"%s\"\n", g->u.file.path);
		break;
	case SHAPE_POV:
		shape_dump(o, g->u.pov);
		break;
	case SHAPE_MESH: {
		const scene_mesh *m = &g->u.mesh;
		fprintf(o, " positions %u normals %u uvs %u faces %u\n", m->n_positions, m->n_normals, m->n_uvs,
			m->n_faces);
		for (uint32_t i = 0; i < m->n_positions; i++)
			fprintf(o, "  v %g %g %g\n", m->positions[i].x, m->positions[i].y, m->positions[i].z);
		for (uint32_t i = 0; i < m->n_normals; i++)
			fprintf(o, "  n %g %g %g\n", m->normals[i].x, m->normals[i].y, m->normals[i].z);
		for (uint32_t i = 0; i < m->n_uvs; i++)
			fprintf(o, "  uv %g %g\n", m->uvs[i].x, m->uvs[i].y);
		for (uint32_t i = 0; i < m->n_faces; i++) {
			fprintf(o, "  f %u %u %u", m->faces[3 * i], m->faces[3 * i + 1], m->faces[3 * i + 2]);
			if (m->normal_idx)
				fprintf(o, " n %u %u %u", m->normal_idx[3 * i], m->normal_idx[3 * i + 1],
					m->normal_idx[3 * i + 2]);
			if (m->uv_idx)
				fprintf(o, " uv %u %u %u", m->uv_idx[3 * i], m->uv_idx[3 * i + 1], m->uv_idx[3 * i + 2]);
			fputc('\n', o);
		}
		break;
	}
	case SHAPE_SUBDIV: {
		const scene_subdiv *c = &g->u.subdiv;
		fprintf(o, " scheme %s boundary %s", c->scheme == SCENE_SUBD_LOOP ? "loop" : "catmull_clark",
			c->boundary == SCENE_SUBD_EDGE_ONLY ? "edge_only" : "edge_and_corner");
		if (c->level > 0)
			fprintf(o, " level %d", c->level);
		else
			fprintf(o, " max_edge %g", c->max_edge_px);
		if (c->file)
			fprintf(o, " file \"%s\"", c->file);
		fprintf(o, " vertices %u faces %u uvs %u creases %u corners %u\n", c->n_vertices, c->n_faces,
			c->n_uvs, c->n_creases, c->n_corners);
		for (uint32_t i = 0; i < c->n_vertices; i++)
			fprintf(o, "  v %g %g %g\n", c->vertices[i].x, c->vertices[i].y, c->vertices[i].z);
		for (uint32_t f = 0, b = 0; f < c->n_faces; b += c->face_sizes[f], f++) {
			fprintf(o, "  f");
			for (uint32_t k = 0; k < c->face_sizes[f]; k++)
				fprintf(o, " %u", c->face_verts[b + k]);
			fputc('\n', o);
		}
		for (uint32_t i = 0; i < c->n_uvs; i++)
			fprintf(o, "  uv %g %g\n", c->uvs[i].x, c->uvs[i].y);
		for (uint32_t f = 0, b = 0; f < c->n_uv_faces; b += c->uv_face_sizes[f], f++) {
			fprintf(o, "  uf");
			for (uint32_t k = 0; k < c->uv_face_sizes[f]; k++)
				fprintf(o, " %u", c->uv_face_verts[b + k]);
			fputc('\n', o);
		}
		for (uint32_t i = 0; i < c->n_creases; i++)
			fprintf(o, "  crease %u %u %g\n", c->creases[i].a, c->creases[i].b, c->creases[i].sharpness);
		for (uint32_t i = 0; i < c->n_corners; i++)
			fprintf(o, "  corner %u %g\n", c->corners[i].vertex, c->corners[i].sharpness);
		break;
	}
	default:
		scene_dump_shape(o, g);
		break;
	}
}

static void dump_xform(FILE *o, const xform *t)
{
	fprintf(o, "  m");
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++) {
			double v = t->m[i][j];
			fprintf(o, " %.6g", fabs(v) < 1e-12 ? 0.0 : v);
		}
	fputc('\n', o);
}

bool scene_cam_face_make(dvec3 p1, dvec3 p2, dvec3 p3, const xform *t, scene_cam_face *out)
{
	dvec3 n = d3_cross(d3_sub(p3, p1), d3_sub(p2, p1));
	double len = d3_length(n);
	if (!(len > 0) || !isfinite(len))
		return false;
	n = d3_scale(n, 1.0 / len);
	dvec3 cen = d3_scale(d3_add(d3_add(p1, p2), p3), 1.0 / 3.0);
	*out = (scene_cam_face){.centroid = d3_to_v3(xform_point(t, cen)),
				.offset = d3_to_v3(xform_vector(t, n)),
				.dir = d3_to_v3(d3_normalize(xform_normal(t, n)))};
	return true;
}

bool scene_cam_uv_face_make(const dvec3 p[3], const dvec3 *n, const vec2 uv[3], const xform *t,
			    scene_cam_uv_face *out)
{
	dvec3 fn = d3_cross(d3_sub(p[2], p[0]), d3_sub(p[1], p[0]));
	double len = d3_length(fn);
	if (!(len > 0) || !isfinite(len))
		return false;
	/* The uv area in double, as the lookup computes it (render/camera.c): not 0 there either. */
	double scale = ((double)uv[1].x - uv[0].x) * ((double)uv[2].y - uv[0].y) -
		       ((double)uv[2].x - uv[0].x) * ((double)uv[1].y - uv[0].y);
	if (!(scale != 0) || !isfinite(scale))
		return false;
	fn = d3_scale(fn, 1.0 / len);
	for (int i = 0; i < 3; i++) {
		dvec3 ni = n ? n[i] : fn;
		out->p[i] = d3_to_v3(xform_point(t, p[i]));
		out->offset[i] = d3_to_v3(xform_vector(t, ni));
		out->dir[i] = d3_to_v3(xform_normal(t, ni));
		out->uv[i] = uv[i];
	}
	return true;
}

/* The cells of face f's uv bounds on a grid of g: false when they miss [0,1]^2 (no pixel's uv
 * lies there). */
static bool uv_face_cells(const scene_cam_uv_face *f, uint32_t g, uint32_t c[4])
{
	double lo[2] = {f->uv[0].x, f->uv[0].y}, hi[2] = {lo[0], lo[1]};
	for (int i = 1; i < 3; i++) {
		double x[2] = {f->uv[i].x, f->uv[i].y};
		for (int a = 0; a < 2; a++)
			lo[a] = fmin(lo[a], x[a]), hi[a] = fmax(hi[a], x[a]);
	}
	if (hi[0] < 0 || hi[1] < 0 || lo[0] > 1 || lo[1] > 1)
		return false;
	c[0] = scene_cam_uv_cell(lo[0], g), c[1] = scene_cam_uv_cell(hi[0], g);
	c[2] = scene_cam_uv_cell(lo[1], g), c[3] = scene_cam_uv_cell(hi[1], g);
	return true;
}

bool scene_cam_uv_index(arena *a, const scene_cam_uv_face *f, uint32_t n, uint32_t *grid,
			const uint32_t **start, const uint32_t **list)
{
	/* About one face a cell, at most 256 x 256; coarser while faces wide in uv would list more than
	 * 4 entries a face (the lookup stays first-match exact at any size). */
	uint32_t g = (uint32_t)ceil(sqrt((double)n));
	g = g < 1 ? 1 : g > 256 ? 256 : g;
	uint64_t total;
	for (;;) {
		total = 0;
		for (uint32_t k = 0; k < n; k++) {
			uint32_t c[4];
			if (uv_face_cells(&f[k], g, c))
				total += (uint64_t)(c[1] - c[0] + 1) * (c[3] - c[2] + 1);
		}
		if (g == 1 || total <= 4 * (uint64_t)n + 1024)
			break;
		g /= 2;
	}
	if (total >= UINT32_MAX)
		return false;
	uint32_t *s = arena_zalloc(a, (size_t)g * g + 1, sizeof *s);
	uint32_t *l = arena_zalloc(a, total ? (size_t)total : 1, sizeof *l);
	if (!s || !l)
		return false;
	for (uint32_t k = 0; k < n; k++) { /* counts, then offsets, then the faces in order */
		uint32_t c[4];
		if (uv_face_cells(&f[k], g, c))
			for (uint32_t j = c[2]; j <= c[3]; j++)
				for (uint32_t i = c[0]; i <= c[1]; i++)
					s[j * g + i + 1]++;
	}
	for (uint32_t i = 0; i < g * g; i++)
		s[i + 1] += s[i];
	uint32_t *fill = arena_zalloc(a, (size_t)g * g, sizeof *fill);
	if (!fill)
		return false;
	memcpy(fill, s, (size_t)g * g * sizeof *fill);
	for (uint32_t k = 0; k < n; k++) {
		uint32_t c[4];
		if (uv_face_cells(&f[k], g, c))
			for (uint32_t j = c[2]; j <= c[3]; j++)
				for (uint32_t i = c[0]; i <= c[1]; i++)
					l[fill[j * g + i]++] = k;
	}
	*grid = g, *start = s, *list = l;
	return true;
}

/* What the camera says beyond POV-Ray's perspective defaults; nothing for those. */
static void dump_camera_more(FILE *o, const scene_camera *c)
{
	static const char *const types[] = {"perspective", "orthographic", "fisheye", "ultra_wide_angle",
					    "panoramic", "cylinder 1", "cylinder 2", "cylinder 3",
					    "cylinder 4", "spherical", "omnimax", "mesh_camera"};
	if (c->type != SCENE_CAM_PERSPECTIVE)
		fprintf(o, " %s", types[c->type]);
	if (c->type == SCENE_CAM_SPHERICAL)
		fprintf(o, " v_angle %g", c->v_angle_deg);
	if (c->type == SCENE_CAM_MESH && c->mesh_distribution == 3)
		fprintf(o, " distribution 3 uv faces %u grid %u%s", c->uv_n, c->uv_grid,
			c->mesh_smooth ? " smooth" : "");
	else if (c->type == SCENE_CAM_MESH)
		fprintf(o, " distribution %d meshes %u faces %u", c->mesh_distribution, c->mesh_count, c->mesh_n);
	if (c->type == SCENE_CAM_MESH && c->mesh_distribution == 1)
		fprintf(o, " rays %u", c->mesh_rays);
	if (c->type == SCENE_CAM_MESH && c->mesh_max_distance > 0)
		fprintf(o, " max_distance %g", c->mesh_max_distance);
	if (c->has_direction)
		dump_d3(o, "direction", c->direction);
	if (!c->has_look_at)
		fprintf(o, " (no look_at)");
	if (c->has_xform)
		for (int r = 0; r < 3; r++)
			fprintf(o, " m%d <%g, %g, %g, %g>", r, c->xf.m[r][0], c->xf.m[r][1], c->xf.m[r][2], c->xf.m[r][3]);
}

void scene_dump(const scene *s, FILE *o)
{
	fprintf(o, "global mm_per_unit %g max_trace_level %d assumed_gamma %g\n", s->global.mm_per_unit,
		s->global.max_trace_level, s->global.assumed_gamma);
	if (s->global.noise_threshold > 0) /* only when set: older dumps stay as they were */
		fprintf(o, "global noise_threshold %g\n", s->global.noise_threshold);
	vec3 al = s->global.ambient_light;
	if (al.x != 1 || al.y != 1 || al.z != 1) {
		fprintf(o, "global");
		dump_v3(o, "ambient_light", al);
		fputc('\n', o);
	}
	if (s->global.subsurface)
		fprintf(o, "global subsurface samples %d %d radiosity %d\n", s->global.subsurface_samples[0],
			s->global.subsurface_samples[1], s->global.subsurface_radiosity);
	if (s->global.radiosity)
		fprintf(o, "global radiosity%s\n", s->global.radiosity_legacy ? " legacy" : "");
	for (const scene_fog *f = s->fogs; f; f = f->next) {
		fprintf(o, "fog type %d", (int)f->type);
		dump_loc(o, f->loc);
		fprintf(o, " distance %g", f->distance);
		dump_v3(o, "color", f->color);
		if (f->type == SCENE_FOG_GROUND) {
			fprintf(o, " offset %g alt %g", f->offset, f->alt);
			dump_d3(o, "up", f->up);
		}
		fputc('\n', o);
	}
	if (s->has_camera) {
		const scene_camera *c = &s->camera;
		fprintf(o, "camera");
		dump_loc(o, c->loc);
		dump_d3(o, "location", c->location);
		dump_d3(o, "look_at", c->look_at);
		dump_d3(o, "sky", c->sky);
		dump_d3(o, "right", c->right);
		dump_d3(o, "up", c->up);
		fprintf(o, " angle %g aperture %g", c->angle_deg, c->aperture);
		if (c->has_focal_point)
			dump_d3(o, "focal_point", c->focal_point);
		dump_camera_more(o, c);
		fputc('\n', o);
		if (c->normal) { /* only then: older dumps stay as they were */
			fprintf(o, "  normal ");
			scene_pigment_dump(o, c->normal);
			fputc('\n', o);
		}
	}
	if (s->has_background) {
		fprintf(o, "background");
		dump_v3(o, "color", s->background);
		if (s->background_circe) /* only then: older dumps stay as they were */
			fprintf(o, " circe");
		fputc('\n', o);
	}
	if (s->has_sky_sphere && s->sky_sphere.n_pigments) {
		fprintf(o, "sky_sphere pigments %d intensity %g", s->sky_sphere.n_pigments, s->sky_sphere.intensity);
		if (s->sky_sphere.has_intensity)
			fprintf(o, " circe");
		dump_d3(o, "rotate", s->sky_sphere.rotate_deg);
		fputc('\n', o);
		for (int i = 0; i < s->sky_sphere.n_pigments; i++) {
			fprintf(o, "  ");
			scene_pigment_dump(o, s->sky_sphere.pigments[i]);
			fputc('\n', o);
		}
	} else if (s->has_sky_sphere) {
		fprintf(o, "sky_sphere image \"%s\" intensity %g", s->sky_sphere.image, s->sky_sphere.intensity);
		dump_d3(o, "rotate", s->sky_sphere.rotate_deg);
		fputc('\n', o);
	}
	static const char *const lk[] = {"point", "sphere", "spot", "parallel", "cylinder"};
	for (size_t i = 0; i < scene_n_lights(s); i++) {
		const scene_light *l = scene_light_at(s, i);
		fprintf(o, "light %s", lk[l->kind]);
		dump_loc(o, l->loc);
		dump_d3(o, "position", l->position);
		dump_v3(o, "color", l->color);
		fprintf(o, " intensity %g", l->intensity);
		if (!l->has_intensity && (l->kind == SCENE_LIGHT_POINT || l->kind == SCENE_LIGHT_SPOT))
			fprintf(o, " falloff none"); /* POV-Ray's rule: no inverse square without intensity */
		if (l->kind == SCENE_LIGHT_SPHERE)
			fprintf(o, " radius %g", l->radius);
		if (l->kind == SCENE_LIGHT_SPOT || l->kind == SCENE_LIGHT_PARALLEL || l->kind == SCENE_LIGHT_CYLINDER)
			dump_d3(o, "point_at", l->point_at);
		if (l->kind == SCENE_LIGHT_SPOT)
			fprintf(o, " cone %g falloff %g", l->cone_deg, l->falloff_deg);
		if (l->kind == SCENE_LIGHT_CYLINDER)
			fprintf(o, " beam %g falloff %g", l->cyl_radius, l->cyl_falloff);
		if (l->tightness != 0)
			fprintf(o, " tightness %g", l->tightness);
		if (l->fade_distance != 0 || l->fade_power != 0)
			fprintf(o, " fade_distance %g fade_power %g", l->fade_distance, l->fade_power);
		if (l->shadowless)
			fprintf(o, " shadowless");
		if (l->no_media)
			fprintf(o, " media_interaction off");
		if (l->area) {
			dump_d3(o, "area", l->axis1);
			dump_d3(o, "and", l->axis2);
			fprintf(o, " %d %d%s%s%s", l->area_n1, l->area_n2, l->circular ? " circular" : "",
				l->orient ? " orient" : "", l->jitter ? " jitter" : "");
		}
		if (l->group)
			fprintf(o, " group %u", l->group);
		if (l->n_projected)
			fprintf(o, " projected_through %u", l->n_projected);
		fputc('\n', o);
		for (uint32_t k = 0; k < l->n_projected; k++) {
			fprintf(o, "  through geom %u", l->projected[k].geom->id);
			dump_loc(o, l->projected[k].loc);
			fputc('\n', o);
			dump_xform(o, &l->projected[k].transform);
		}
	}
	if (s->atmosphere) {
		fprintf(o, "atmosphere");
		dump_loc(o, s->atmosphere->loc);
		dump_media(o, s->atmosphere);
		fputc('\n', o);
	}
	for (size_t i = 0; i < s->light_groups.len; i++) {
		const scene_light_group *g = &VECBUF_AT(&s->light_groups, scene_light_group, i);
		fprintf(o, "light_group %zu parent %u global_lights %s", i + 1, g->parent, g->global_lights ? "on" : "off");
		dump_loc(o, g->loc);
		fputc('\n', o);
	}
	/* Oldest first: the lists are built newest first. */
	const scene_material **mats = mem_alloc(s->n_materials ? s->n_materials : 1, sizeof *mats);
	if (mats) {
		for (const scene_material *m = s->materials; m; m = m->next)
			mats[m->id] = m;
		for (uint32_t i = 0; i < s->n_materials; i++)
			dump_material(o, mats[i]);
		mem_free(mats);
	}
	const scene_geom **geoms = mem_alloc(s->n_geoms ? s->n_geoms : 1, sizeof *geoms);
	if (geoms) {
		for (const scene_geom *g = s->geoms; g; g = g->next)
			geoms[g->id] = g;
		for (uint32_t i = 0; i < s->n_geoms; i++)
			dump_geom(o, geoms[i]);
		mem_free(geoms);
	}
	for (size_t i = 0; i < scene_n_objects(s); i++) {
		const scene_object *ob = scene_object_at(s, i);
		fprintf(o, "object %zu geom %u material ", i, ob->geom->id);
		if (ob->material)
			fprintf(o, "%u", ob->material->id);
		else
			fprintf(o, "default");
		if (ob->no_shadow)
			fprintf(o, " no_shadow");
		if (ob->instance)
			fprintf(o, " instance");
		if (ob->inverse)
			fprintf(o, " inverse");
		if (ob->clip_only)
			fprintf(o, " clip");
		if (ob->csg_depth) { /* the path from the solid's root: operator, node id, operand */
			static const char *const ops[] = {"union", "intersection", "difference", "merge"};
			fprintf(o, " csg");
			for (uint32_t k = 0; k < ob->csg_depth; k++)
				fprintf(o, " %s%s#%u.%u", ob->csg[k].inverse ? "inverse-" : "", ops[ob->csg[k].op],
					ob->csg[k].id, ob->csg[k].operand);
		}
		dump_pov_flags(o, ob->pov_flags);
		if (ob->light_group)
			fprintf(o, " light_group %u", ob->light_group);
		for (uint32_t k = 0; k < ob->n_parts; k++) /* a blob's component textures, part k + 1's */
			fprintf(o, " part%u material %u", k + 1, ob->part_mat[k]->id);
		if (ob->pieces)
			fprintf(o, " piece %u of %u", ob->piece, ob->pieces);
		dump_loc(o, ob->loc);
		fputc('\n', o);
		dump_xform(o, &ob->transform);
	}
}

/* datafile.c - POV-Ray 3.7's data files: #fopen, #read, #write, #fclose and defined(Name).
 * A data file lies in the scene's folder or an -I folder (a path that leaves them is refused,
 * saying why: a scene is text from anywhere and must not read or write the rest of the disk).
 * A file open for reading is read whole and lexed with the scene's lexer, so an error in it is
 * quoted at its line; #read takes its comma-separated floats, vectors and strings, and the name
 * is undeclared once the last value is read, as in POV-Ray (`#while (defined(F))`). Writes
 * happen while the scene is parsed, under `circe check` as under `circe render`, as POV-Ray
 * writes while it parses: a scene that writes a file and reads it back behaves alike. */
#include "lang/parser.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Data files open at once: each holds a stream (writing) or the file's text (reading); a loop
 * that opens without closing meets this limit long before the system's. */
enum { LANG_MAX_DATA_FILES = 32 };

typedef enum { DATA_READ, DATA_WRITE, DATA_APPEND } data_mode;

typedef struct lang_datafile {
	const char *name; /* the identifier of #fopen */
	const char *path; /* as opened */
	const char *given; /* as the scene wrote it, for messages */
	diag_loc loc; /* its #fopen */
	data_mode mode;
	bool open;
	bool ended; /* reading: closed after its last value (#read past it is the error) */
	diag_loc last_read; /* reading: the #read that took the last value */
	FILE *out; /* writing */
	lang_lexer lx; /* reading */
} lang_datafile;

static lang_datafile *file_at(parser *p, int i) { return &VECBUF_AT(&p->datafiles, lang_datafile, (size_t)i); }

/* ---- paths ------------------------------------------------------------------------------- */

/* The folder of path ("." for a bare name), in the arena. */
static char *folder_of(parser *p, const char *path)
{
	const char *slash = strrchr(path, '/');
	if (!slash)
		return arena_strdup(&p->sc->arena, ".");
	if (slash == path)
		return arena_strdup(&p->sc->arena, "/");
	return arena_strndup(&p->sc->arena, path, (size_t)(slash - path));
}

/* dir/name; name alone when dir is "." (a scene named without a folder), as messages show it. */
static char *join(parser *p, const char *dir, const char *name)
{
	if (!strcmp(dir, "."))
		return arena_strdup(&p->sc->arena, name);
	size_t dl = strlen(dir), nl = strlen(name);
	char *s = arena_alloc(&p->sc->arena, dl + nl + 2, 1, 1);
	if (!s)
		return NULL;
	memcpy(s, dir, dl);
	s[dl] = '/';
	memcpy(s + dl + 1, name, nl + 1);
	return s;
}

/* True when canonical path lies in the canonical folder root. */
static bool inside(const char *path, const char *root)
{
	size_t n = strlen(root);
	if (strncmp(path, root, n))
		return false;
	return root[n - 1] == '/' || path[n] == '/' || path[n] == '\0';
}

/* path itself when it lies in the scene's folder or an -I folder: its folder resolved by
 * realpath (links included) lies in one of theirs, and its last name is a name (not "." or
 * ".."). NULL (nothing reported) when it lies elsewhere or its folder does not exist. */
static char *confined(parser *p, const char *path)
{
	char *dir = folder_of(p, path);
	const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
	if (!dir || !*base || !strcmp(base, ".") || !strcmp(base, ".."))
		return NULL;
	char *canon = realpath(dir, NULL);
	if (!canon)
		return NULL;
	bool ok = false;
	for (size_t i = 0; i <= p->opt.n_include_dirs && !ok; i++) {
		const char *root_dir = i == 0 ? folder_of(p, p->files[0].path) : p->opt.include_dirs[i - 1];
		char *root = root_dir ? realpath(root_dir, NULL) : NULL;
		ok = root && inside(canon, root);
		free(root);
	}
	free(canon);
	return ok ? (char *)path : NULL;
}

/* Under a reader that is not the file system (a fuzzer's), nothing is resolved on the disk: a
 * relative name without ".." in the scene's folder. */
static char *confined_virtual(parser *p, const char *name)
{
	if (name[0] == '/' || !strcmp(name, "..") || !strncmp(name, "../", 3) || strstr(name, "/../") ||
	    (strlen(name) >= 3 && !strcmp(name + strlen(name) - 3, "/..")))
		return NULL;
	return join(p, folder_of(p, p->files[0].path), name);
}

static bool outside(parser *p, diag_loc loc, const char *name)
{
	return lang_error(p, loc,
			  "data file '%s' is outside the scene's folder and the -I folders: circe reads and writes "
			  "data files only there (give its folder with -I to allow it)",
			  name);
}

/* ---- #fopen ------------------------------------------------------------------------------ */

static bool mode_word(const lang_token *t, data_mode *m)
{
	static const char *const words[] = {"read", "write", "append"};
	if (t->kind != LTK_UNSUPPORTED && t->kind != LTK_IDENT)
		return false;
	for (int i = 0; i < 3; i++)
		if (t->len == strlen(words[i]) && !memcmp(t->text, words[i], t->len)) {
			*m = (data_mode)i;
			return true;
		}
	return false;
}

/* Reads the file at path into a lexer; false after reporting. */
static bool open_for_reading(parser *p, lang_datafile *f, diag_loc at, const char *name)
{
	char *text = NULL;
	size_t len = 0;
	int err = p->opt.read(p->opt.read_user, f->path, &text, &len);
	if (err)
		return lang_error(p, at, "cannot open data file '%s' for reading: %s", name, strerror(err));
	char *owned = mem_realloc(text, len + 1, 1); /* room for the NUL */
	if (!owned) {
		mem_free(text);
		return lang_error(p, at, "out of memory");
	}
	const diag_source *src = diag_adopt_source(p->d, f->path, owned, len);
	if (!src)
		return lang_error(p, at, "out of memory");
	lang_lexer_init(&f->lx, src);
	return true;
}

/* The path a data file opens at: for reading the first of the scene's folder and the -I folders
 * that has it; for writing the scene's folder (or where the name points, inside them). */
static bool resolve(parser *p, diag_loc at, const char *name, data_mode mode, const char **out)
{
	bool disk = p->opt.read == lang_read_file;
	if (!disk) {
		if (mode != DATA_READ)
			return lang_error(p, at, "writing data file '%s' needs the file system (this parse reads "
						 "through another reader)",
					  name);
		return (*out = confined_virtual(p, name)) || outside(p, at, name);
	}
	size_t n_dirs = mode == DATA_READ && name[0] != '/' ? 1 + p->opt.n_include_dirs : 1;
	const char *first = NULL;
	for (size_t i = 0; i < n_dirs; i++) {
		const char *dir = i == 0 ? folder_of(p, p->files[0].path) : p->opt.include_dirs[i - 1];
		const char *path = name[0] == '/' ? name : join(p, dir, name);
		if (!path)
			return lang_error(p, at, "out of memory");
		char *c = confined(p, path);
		if (!c)
			continue;
		if (!first)
			first = c;
		FILE *probe = mode == DATA_READ ? fopen(c, "rb") : NULL;
		if (probe) {
			fclose(probe);
			*out = c;
			return true;
		}
	}
	if (!first)
		return outside(p, at, name);
	*out = first; /* writing; or reading a file that is nowhere: its error comes when opened */
	return true;
}

static int find_file(parser *p, const char *name, size_t len, bool open_only)
{
	for (size_t i = p->datafiles.len; i-- > 0;) {
		const lang_datafile *f = file_at(p, (int)i);
		if ((!open_only || f->open) && strlen(f->name) == len && !memcmp(f->name, name, len))
			return (int)i;
	}
	return -1;
}

static int open_count(parser *p)
{
	int n = 0;
	for (size_t i = 0; i < p->datafiles.len; i++)
		n += file_at(p, (int)i)->open;
	return n;
}

/* The identifier that comes next (consumed, not macro-expanded) into *name: a data file's name
 * after `what` ("'#fopen'", "'#read'"). */
static bool file_name(parser *p, const char *what, lang_token *name)
{
	p->no_expand = true;
	*name = *lang_peek(p);
	p->no_expand = false;
	if (name->kind != LTK_IDENT)
		return lang_error_found(p, "expected the data file's name %s", what);
	lang_advance(p);
	return true;
}

/* fopen = "#fopen" identifier string ( "read" | "write" | "append" ) */
bool lang_fopen(parser *p, diag_loc at)
{
	lang_token name;
	TRY(file_name(p, "after '#fopen'", &name));
	int old = find_file(p, name.text, name.len, true);
	if (old >= 0)
		return lang_error(p, name.loc, "'%.*s' is already an open data file (opened at line %u): #fclose it first",
				  (int)name.len, name.text, file_at(p, old)->loc.line);
	const symbol *s = lang_lookup(p, name.text, name.len);
	if (s)
		return lang_error(p, name.loc, "'%.*s' is already declared (%s): a data file needs a new name", (int)name.len,
				  name.text, lang_value_kind_name(&s->val));
	diag_loc sloc = lang_peek(p)->loc;
	const char *file;
	TRY(lang_string(p, "after the data file's name in '#fopen'", &file));
	data_mode mode;
	if (!mode_word(lang_peek(p), &mode))
		return lang_error_found(p, "expected read, write or append after the file in '#fopen'");
	lang_advance(p);
	if (open_count(p) >= LANG_MAX_DATA_FILES)
		return lang_error(p, at, "too many data files open at once (limit is %d)", LANG_MAX_DATA_FILES);
	lang_datafile f = {.loc = at, .mode = mode, .open = true, .given = file};
	TRY(f.name = arena_strndup(&p->sc->arena, name.text, name.len));
	TRY(resolve(p, sloc, file, mode, &f.path));
	if (mode == DATA_READ) {
		TRY(open_for_reading(p, &f, sloc, file));
	} else if (!(f.out = fopen(f.path, mode == DATA_WRITE ? "w" : "a"))) {
		return lang_error(p, sloc, "cannot open data file '%s' for writing: %s", file, strerror(errno));
	}
	if (!vecbuf_push(&p->datafiles, &f)) {
		if (f.out)
			fclose(f.out);
		return lang_error(p, at, "out of memory");
	}
	value v = {.kind = VAL_FILE, .file = (int)p->datafiles.len - 1};
	return lang_define(p, &name, false, &v);
}

/* ---- #fclose ----------------------------------------------------------------------------- */

static bool close_file(parser *p, lang_datafile *f, diag_loc at)
{
	f->open = false;
	if (f->out) {
		bool ok = fclose(f->out) == 0;
		f->out = NULL;
		if (!ok)
			return lang_error(p, at, "cannot write data file '%s': %s", f->given, strerror(errno));
	}
	return true;
}

/* fclose = "#fclose" identifier   (of a file not open: a warning, as #undef of an unknown name) */
bool lang_fclose(parser *p)
{
	lang_token name;
	TRY(file_name(p, "after '#fclose'", &name));
	int i = find_file(p, name.text, name.len, true);
	const symbol *s = lang_lookup(p, name.text, name.len);
	if (i < 0 || !s || s->val.kind != VAL_FILE) {
		diag_warning(p->d, name.loc, "'#fclose' of '%.*s', which is not an open data file", (int)name.len, name.text);
		return true;
	}
	lang_forget(p, name.text, name.len);
	return close_file(p, file_at(p, i), name.loc);
}

void lang_datafiles_init(parser *p) { vecbuf_init(&p->datafiles, sizeof(lang_datafile)); }

/* At the end of the parse (or its failure): every stream written is closed. */
void lang_datafiles_close(parser *p)
{
	for (size_t i = 0; i < p->datafiles.len; i++) {
		lang_datafile *f = file_at(p, (int)i);
		if (f->open)
			close_file(p, f, f->loc);
	}
	vecbuf_free(&p->datafiles);
}

/* ---- #read ------------------------------------------------------------------------------- */

/* The open data file named by the identifier that comes next (consumed); what: "#read". */
static lang_datafile *named_file(parser *p, const char *what, data_mode want)
{
	lang_token name;
	char in[32];
	snprintf(in, sizeof in, "in '%s'", what);
	if (!file_name(p, in, &name))
		return NULL;
	const symbol *s = lang_lookup(p, name.text, name.len);
	if (!s) {
		int e = find_file(p, name.text, name.len, false);
		lang_datafile *f = e >= 0 ? file_at(p, e) : NULL;
		if (f && f->ended && want == DATA_READ)
			lang_error(p, name.loc,
				   "'#read' past the end of data file '%s': its last value was read at line %u, which "
				   "closed '%.*s' (test defined(%.*s) before reading)",
				   f->given, f->last_read.line, (int)name.len, name.text, (int)name.len, name.text);
		else
			lang_error(p, name.loc, "undeclared identifier '%.*s'", (int)name.len, name.text);
		return NULL;
	}
	if (s->val.kind != VAL_FILE) {
		lang_error(p, name.loc, "'%.*s' is %s, not a data file", (int)name.len, name.text, lang_value_kind_name(&s->val));
		return NULL;
	}
	lang_datafile *f = file_at(p, s->val.file);
	bool reading = f->mode == DATA_READ;
	if (reading != (want == DATA_READ)) {
		lang_error(p, name.loc, "'%s' of '%.*s', which is open for %s (at line %u)", what, (int)name.len, name.text,
			   reading ? "reading" : "writing", f->loc.line);
		return NULL;
	}
	return f;
}

/* A token of the data file; false after reporting a lexical error. */
static bool data_token(parser *p, lang_datafile *f, lang_token *t)
{
	if (lang_lex(&f->lx, p->d, t))
		return true;
	p->failed = true;
	return false;
}

static bool data_error(parser *p, const lang_token *t, const char *what)
{
	char found[300];
	return lang_error(p, t->loc, "expected %s in the data file, found %s", what, lang_describe(t, found, sizeof found));
}

/* number = [ "-" | "+" ] a number, t its first token */
static bool data_number(parser *p, lang_datafile *f, lang_token *t, double *x)
{
	double sign = 1;
	if (t->kind == LTK_MINUS || t->kind == LTK_PLUS) {
		sign = t->kind == LTK_MINUS ? -1 : 1;
		TRY(data_token(p, f, t));
	}
	if (t->kind != LTK_NUMBER)
		return data_error(p, t, "a number");
	*x = sign * t->number;
	return true;
}

/* data_value = number | string | "<" number { "," number } ">"   (2 to LANG_MAX_VECTOR numbers) */
static bool data_value(parser *p, lang_datafile *f, value *out)
{
	lang_token t;
	TRY(data_token(p, f, &t));
	memset(out, 0, sizeof *out);
	if (t.kind == LTK_STRING)
		return lang_decode_string(p, &t, out);
	if (t.kind != LTK_LT) {
		out->kind = VAL_FLOAT, out->n = 1;
		return data_number(p, f, &t, &out->v[0]);
	}
	diag_loc open = t.loc;
	for (;;) {
		TRY(data_token(p, f, &t));
		if (out->n == LANG_MAX_VECTOR)
			return lang_error(p, t.loc, "vector has too many components (limit is %d)", LANG_MAX_VECTOR);
		TRY(data_number(p, f, &t, &out->v[out->n++]));
		TRY(data_token(p, f, &t));
		if (t.kind == LTK_GT)
			break;
		if (t.kind != LTK_COMMA)
			return data_error(p, &t, "',' or '>' in a vector");
	}
	if (out->n < 2)
		return lang_error(p, open, "a vector in a data file has 2 to %d components, found 1", LANG_MAX_VECTOR);
	out->kind = VAL_VECTOR;
	return true;
}

/* Whether the next token of the data file is of kind k; consumed when it is and consume. */
static bool data_next(parser *p, lang_datafile *f, lang_tok k, bool consume, bool *is)
{
	lang_lexer save = f->lx;
	lang_token t;
	TRY(data_token(p, f, &t));
	*is = t.kind == k;
	if (!*is || !consume)
		f->lx = save;
	return true;
}

/* The end of a data file read: closed and its name undeclared, as in POV-Ray 3.7. */
static bool end_of_data(parser *p, lang_datafile *f, diag_loc at)
{
	f->ended = true;
	f->last_read = at;
	lang_forget(p, f->name, strlen(f->name));
	return close_file(p, f, at);
}

/* One name of #read given the file's next value. As povray 3.7.0 does: a value not followed by
 * ',' that ends the file closes it; a name met at the end of the file closes it and is not
 * declared (circe warns: the name keeps what it had). */
static bool read_one(parser *p, lang_datafile *f, const lang_token *name, lang_array *arr, size_t index, diag_loc at)
{
	bool end, comma;
	TRY(data_next(p, f, LTK_EOF, false, &end));
	if (end) {
		diag_warning(p->d, name->loc,
			     "'#read' at the end of data file '%s': '%.*s' is not read; the file is closed and its name "
			     "undeclared",
			     f->given, (int)name->len, name->text);
		return end_of_data(p, f, at);
	}
	value v;
	TRY(data_value(p, f, &v));
	TRY(arr ? lang_array_store(p, name->loc, arr, index, &v) : lang_define(p, name, false, &v));
	TRY(data_next(p, f, LTK_COMMA, true, &comma));
	if (comma)
		return true;
	TRY(data_next(p, f, LTK_EOF, false, &end));
	return !end || end_of_data(p, f, at);
}

/* read = "#read" "(" identifier "," target { "," target } ")"   target = identifier [ index ]
 * Each name is declared (as by #declare) with the file's next value; an array's element is
 * assigned (povray 3.7 reads into an element already set; circe into any). */
bool lang_read_directive(parser *p, diag_loc at)
{
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	bool ok = lang_expect(p, LTK_LPAREN, "after '#read'");
	lang_datafile *f = ok ? named_file(p, "#read", DATA_READ) : NULL;
	ok = f != NULL;
	int n = 0;
	while (ok && !lang_accept(p, LTK_RPAREN)) {
		if (!lang_expect(p, LTK_COMMA, "between the names of '#read'")) {
			ok = false;
			break;
		}
		p->no_expand = true;
		lang_token name = *lang_peek(p);
		p->no_expand = false;
		if (name.kind != LTK_IDENT) {
			ok = lang_error_found(p, "expected a name to read into in '#read'");
			break;
		}
		lang_advance(p);
		n++;
		lang_array *arr = NULL;
		size_t index = 0;
		if (lang_peek(p)->kind == LTK_LBRACKET && !lang_element_target(p, &name, &arr, &index)) {
			ok = false;
			break;
		}
		if (!f->ended) /* the names after the end are left as they are */
			ok = read_one(p, f, &name, arr, index, at);
	}
	if (ok && n == 0)
		ok = lang_error(p, p->prev.loc, "'#read' needs a name to read into after the data file");
	p->directive_expr = false;
	return ok;
}

/* ---- #write ------------------------------------------------------------------------------ */

/* One value written as POV-Ray 3.7 writes it: a string as it is, a float as %g, a vector as
 * <%g,%g,...> and a blank. */
static bool write_value(parser *p, lang_datafile *f, const value *v, diag_loc loc)
{
	switch (v->kind) {
	case VAL_STRING: fputs(v->str, f->out); return true;
	case VAL_FLOAT: fprintf(f->out, "%g", v->v[0]); return true;
	case VAL_VECTOR:
		fputc('<', f->out);
		for (int i = 0; i < v->n; i++)
			fprintf(f->out, i ? ",%g" : "%g", v->v[i]);
		fputs("> ", f->out);
		return true;
	default:
		return lang_error(p, loc, "'#write' writes floats, vectors and strings, found %s", lang_value_kind_name(v));
	}
}

/* write = "#write" "(" identifier [ "," ] expression { [ "," ] expression } ")"
 * The commas are optional, as POV-Ray 3.7's Parse_Comma makes them (its portfolio's html_gen.inc
 * writes `#write(HTMLFile Header1)`). */
bool lang_write_directive(parser *p)
{
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	bool ok = lang_expect(p, LTK_LPAREN, "after '#write'");
	lang_datafile *f = ok ? named_file(p, "#write", DATA_WRITE) : NULL;
	ok = f != NULL;
	while (ok && !lang_accept(p, LTK_RPAREN)) {
		lang_accept(p, LTK_COMMA);
		value v;
		diag_loc loc = lang_peek(p)->loc;
		ok = ok && lang_expr(p, &v) && write_value(p, f, &v, loc);
	}
	p->directive_expr = false;
	if (ok && ferror(f->out))
		return lang_error(p, f->loc, "cannot write data file '%s': %s", f->given, strerror(errno));
	return ok;
}

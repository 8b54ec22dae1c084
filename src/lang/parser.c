/* parser.c - the token stream of the scene language: a stack of lexers for #include, the
 * directives (#declare, #local, #if, #else, #while, #end, #version) run at token level so they may
 * stand anywhere (inside blocks too), the symbol table, and expressions evaluated at parse time.
 * The first error is reported and ends the parse: every function returns false from then on. */
#include "lang/parser.h"

#include "base/rng.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

enum { DEFAULT_TOTAL_ITERATIONS = 10000000 }; /* all #while loops of one parse together */

/* ---- errors ------------------------------------------------------------------------------ */

static void vreport(parser *p, diag_kind kind, diag_loc loc, const char *fmt, va_list ap)
{
	diag_vreport(p->d, kind, loc, fmt, ap);
}

bool lang_error(parser *p, diag_loc loc, const char *fmt, ...)
{
	if (p->failed)
		return false;
	p->failed = true;
	va_list ap;
	va_start(ap, fmt);
	vreport(p, DIAG_ERROR, loc, fmt, ap);
	va_end(ap);
	return false;
}

static void note(parser *p, diag_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void note(parser *p, diag_loc loc, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vreport(p, DIAG_NOTE, loc, fmt, ap);
	va_end(ap);
}

const char *lang_describe(const lang_token *t, char *buf, size_t size)
{
	switch (t->kind) {
	case LTK_NUMBER:
		snprintf(buf, size, "'%.*s'", t->len > 40 ? 40 : (int)t->len, t->text);
		break;
	case LTK_STRING:
		snprintf(buf, size, "string \"%.*s\"", t->len > 40 ? 40 : (int)t->len, t->text);
		break;
	case LTK_IDENT:
		snprintf(buf, size, "identifier '%.*s'", (int)t->len, t->text);
		break;
	case LTK_UNSUPPORTED:
		snprintf(buf, size, "'%.*s'", (int)t->len, t->text);
		break;
	case LTK_UNSUPPORTED_DIRECTIVE:
		snprintf(buf, size, "'#%.*s'", (int)t->len, t->text);
		break;
	default:
		snprintf(buf, size, "%s", lang_tok_name(t->kind));
	}
	return buf;
}

/* The message for a token outside the language, or NULL. */
static bool report_unsupported(parser *p, const lang_token *t)
{
	if (t->kind != LTK_UNSUPPORTED && t->kind != LTK_UNSUPPORTED_DIRECTIVE)
		return false;
	lang_error(p, t->loc, "'%s%.*s' is not supported by circe", t->kind == LTK_UNSUPPORTED ? "" : "#", (int)t->len,
		   t->text);
	return true;
}

bool lang_error_found(parser *p, const char *fmt, ...)
{
	lang_token *t = lang_peek(p);
	if (p->failed)
		return false;
	if (report_unsupported(p, t))
		return false;
	char what[512], found[300];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(what, sizeof what, fmt, ap);
	va_end(ap);
	return lang_error(p, t->loc, "%s, found %s", what, lang_describe(t, found, sizeof found));
}

/* The one message for every limit of LANG_MAX_DEPTH: recursion and open #if/#while alike. */
static bool nesting_too_deep(parser *p, diag_loc loc)
{
	return lang_error(p, loc, "nesting too deep (limit is %d levels)", LANG_MAX_DEPTH);
}

bool lang_enter(parser *p, diag_loc loc)
{
	if (++p->depth > LANG_MAX_DEPTH) {
		p->depth--;
		return nesting_too_deep(p, loc);
	}
	return true;
}

/* The value of a string token, escapes resolved, in the scene arena. */
bool lang_decode_string(parser *p, const lang_token *s, value *out)
{
	char *buf = arena_alloc(&p->sc->arena, s->len + 1, 1, 1);
	if (!buf)
		return lang_error(p, s->loc, "out of memory");
	size_t k = 0;
	for (uint32_t i = 0; i < s->len; i++)
		buf[k++] = s->text[i] == '\\' ? lang_string_escape(s->text[++i]) : s->text[i];
	buf[k] = '\0';
	out->kind = VAL_STRING;
	out->n = 0;
	out->str = buf, out->mat = NULL, out->obj = NULL;
	return true;
}

/* ---- files ------------------------------------------------------------------------------- */

int lang_read_file(void *user, const char *path, char **text, size_t *len)
{
	(void)user;
	FILE *f = fopen(path, "rb");
	if (!f)
		return errno ? errno : ENOENT;
	struct stat st;
	bool known = fstat(fileno(f), &st) == 0, regular = known && S_ISREG(st.st_mode);
	if (known && S_ISDIR(st.st_mode)) { /* fopen opens a directory; ftell would size it huge */
		fclose(f);
		return EISDIR;
	}
	size_t cap = 1 << 16, n = 0;
	if (regular && fseek(f, 0, SEEK_END) == 0) { /* size the buffer once for a regular file */
		long size = ftell(f);
		if (size > 0 && (unsigned long)size < SIZE_MAX - 2)
			cap = (size_t)size + 2;
		rewind(f);
	}
	char *buf = mem_alloc(cap, 1);
	if (!buf) {
		fclose(f);
		return ENOMEM;
	}
	for (;;) {
		if (n == cap) {
			char *nb = cap < SIZE_MAX / 2 ? mem_realloc(buf, cap * 2, 1) : NULL;
			if (!nb) {
				mem_free(buf);
				fclose(f);
				return ENOMEM;
			}
			buf = nb;
			cap *= 2;
		}
		size_t got = fread(buf + n, 1, cap - n, f);
		n += got;
		if (got == 0)
			break;
	}
	int err = ferror(f) ? (errno ? errno : EIO) : 0;
	fclose(f);
	if (err) {
		mem_free(buf);
		return err;
	}
	*text = buf;
	*len = n;
	return 0;
}

/* Files at least this large are mapped rather than read, and the pages the lexer has left
 * behind are dropped as it goes: a 100 MB mesh then never holds 100 MB of text at once. */
enum { MAP_MIN_BYTES = 1 << 20, RELEASE_STEP = 8 << 20, RELEASE_MARGIN = 1 << 20 };

/* Maps a large regular file; 0, an errno value, or -1 when the file should be read instead. */
static int map_source(parser *p, const char *path, const diag_source **out)
{
	int fd = open(path, O_RDONLY);
	if (fd < 0)
		return errno ? errno : ENOENT;
	struct stat st;
	if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size < MAP_MIN_BYTES) {
		close(fd);
		return -1;
	}
	size_t len = (size_t)st.st_size;
	void *map = mmap(NULL, len, PROT_READ, MAP_PRIVATE, fd, 0);
	close(fd);
	if (map == MAP_FAILED)
		return -1;
	const unsigned char *b = map;
	size_t skip = b[0] == 0xEF && b[1] == 0xBB && b[2] == 0xBF ? 3 : 0;
	*out = diag_adopt_mapped(p->d, path, map, len, skip);
	return *out ? 0 : ENOMEM;
}

/* Hands the pages of a mapped source that lie well behind the lexer back to the kernel. They are
 * clean file pages: quoting a line there, or a #while jumping back, faults them in again. */
/* ---- the token memo ----------------------------------------------------------------------
 * A #while or #for body and a macro's body are read again at each turn; their tokens are lexed
 * once and remembered by where the lexer stood (and where its text ends: a macro frame's lexer
 * stops at the body's #end): the lexer is a pure function of that position, and the sources stay
 * in place for the whole parse. Only successful reads are kept (an error is lexed, and reported,
 * again), only while a loop or a macro runs, and at most MEMO_MAX of them. */
enum { MEMO_MIN = 1024, MEMO_MAX = 1 << 18 };

struct lex_memo {
	const char *at, *end; /* at NULL: a free slot */
	lang_lexer after;
	lang_token tok;
};

static size_t memo_slot(const char *at, size_t cap)
{
	uint64_t h = (uint64_t)(uintptr_t)at * 0x9e3779b97f4a7c15u;
	return (size_t)(h >> 32) & (cap - 1);
}

static struct lex_memo *memo_find(parser *p, const lang_lexer *lx)
{
	if (!p->memo)
		return NULL;
	for (size_t i = memo_slot(lx->p, p->memo_cap);; i = (i + 1) & (p->memo_cap - 1)) {
		struct lex_memo *m = &p->memo[i];
		if (!m->at || (m->at == lx->p && m->end == lx->end))
			return m;
	}
}

/* True while a #while or #for runs, or a macro's body is read. */
static bool memo_wanted(const parser *p)
{
	if (p->n_macro_calls > 0)
		return true;
	for (int i = p->n_conds - 1; i >= 0; i--)
		if (p->conds[i].kind == COND_WHILE || p->conds[i].kind == COND_FOR)
			return true;
	return false;
}

static void memo_put(parser *p, const char *at, const char *end, const lang_lexer *after, const lang_token *t)
{
	if (p->memo_n + 1 > p->memo_cap / 2) { /* grow, keeping the load under one half */
		if (p->memo_cap >= MEMO_MAX)
			return;
		size_t cap = p->memo_cap ? p->memo_cap * 2 : MEMO_MIN;
		struct lex_memo *old = p->memo, *m = mem_calloc(cap, sizeof *m);
		if (!m)
			return; /* the memo is an optimisation: without memory, lex again */
		size_t old_cap = p->memo_cap;
		p->memo = m, p->memo_cap = cap;
		for (size_t i = 0; i < old_cap; i++)
			if (old[i].at) {
				lang_lexer k = {.p = old[i].at, .end = old[i].end};
				*memo_find(p, &k) = old[i];
			}
		mem_free(old);
	}
	lang_lexer k = {.p = at, .end = end};
	struct lex_memo *m = memo_find(p, &k);
	if (!m->at)
		p->memo_n++;
	*m = (struct lex_memo){at, end, *after, *t};
}

/* lang_lex through the memo. */
static bool lex(parser *p, lang_lexer *lx, diag *d, lang_token *t)
{
	struct lex_memo *m = memo_find(p, lx);
	if (m && m->at) {
		*t = m->tok;
		*lx = m->after;
		return true;
	}
	const char *at = lx->p;
	if (!lang_lex(lx, d, t))
		return false;
	if (memo_wanted(p))
		memo_put(p, at, lx->end, lx, t);
	return true;
}

static void release_behind(include_frame *f)
{
	const diag_source *src = f->lx.src;
	if (!src->map || f->lx.p - f->released < RELEASE_STEP)
		return;
	uintptr_t page = (uintptr_t)sysconf(_SC_PAGESIZE);
	uintptr_t from = ((uintptr_t)f->released + page - 1) & ~(page - 1);
	uintptr_t to = ((uintptr_t)f->lx.p - RELEASE_MARGIN) & ~(page - 1);
	if (to > from) {
#ifdef MADV_DONTNEED
		madvise((void *)from, to - from, MADV_DONTNEED);
#endif
		f->released = (const char *)to;
	}
}

/* Reads path through the hook and registers it with diag (BOM removed). 0 or an errno value.
 * The text is handed to diag, not copied: a 100 MB mesh is held once. */
static int open_source(parser *p, const char *path, const diag_source **out)
{
	if (p->opt.read == lang_read_file) {
		int err = map_source(p, path, out);
		if (err >= 0)
			return err;
	}
	char *text = NULL;
	size_t len = 0;
	int err = p->opt.read(p->opt.read_user, path, &text, &len);
	if (err)
		return err;
	size_t skip = 0;
	if (len >= 3 && (unsigned char)text[0] == 0xEF && (unsigned char)text[1] == 0xBB && (unsigned char)text[2] == 0xBF)
		skip = 3;
	char *owned = mem_realloc(text, len + 1, 1); /* room for the NUL */
	if (!owned) {
		mem_free(text);
		return ENOMEM;
	}
	if (skip)
		memmove(owned, owned + skip, len - skip);
	*out = diag_adopt_source(p->d, path, owned, len - skip);
	return *out ? 0 : ENOMEM;
}

static bool push_file(parser *p, const diag_source *src, const char *path, diag_loc at)
{
	include_frame *f = &p->files[p->n_files++];
	lang_lexer_init(&f->lx, src);
	f->path = path;
	f->included_at = at;
	f->cond_base = p->n_conds;
	f->released = src->text;
	f->macro = NULL;
	return true;
}

/* The chain of includes and macro calls, innermost first, as notes. */
static void note_chain(parser *p)
{
	enum { SHOWN = 8 }; /* innermost and outermost links; the middle of a deep chain is noise */
	for (int i = p->n_files - 1; i >= 1; i--) {
		if (i == p->n_files - 1 - SHOWN && i > SHOWN) {
			int calls = 0;
			for (int k = SHOWN + 1; k <= i; k++)
				calls += p->files[k].macro != NULL;
			note(p, diag_noloc(), "... %d more %s ...", i - SHOWN,
			     calls == 0 ? "includes" : calls == i - SHOWN ? "macro calls" : "includes or macro calls");
			i = SHOWN;
		}
		if (p->files[i].macro)
			note(p, p->files[i].included_at, "'%s' called from here", p->files[i].macro->name);
		else
			note(p, p->files[i].included_at, "'%s' is included from here", p->files[i].path);
	}
}

static char *join_path(parser *p, const char *dir, size_t dlen, const char *name)
{
	size_t nlen = strlen(name);
	char *s = arena_alloc(&p->sc->arena, dlen + nlen + 2, 1, 1);
	if (!s)
		return NULL;
	memcpy(s, dir, dlen);
	size_t k = dlen;
	if (dlen && dir[dlen - 1] != '/')
		s[k++] = '/';
	memcpy(s + k, name, nlen + 1);
	return s;
}

static bool no_memory(parser *p, diag_loc loc) { return lang_error(p, loc, "out of memory"); }

/* include = "#include" ( string | identifier ) -- read raw: a lookahead here would run ahead
 * of the included text. Searched in the including file's folder, then each -I folder. */
static bool do_include(parser *p, diag_loc at)
{
	const char *name;
	lang_token t;
	if (!lex(p, &p->files[p->n_files - 1].lx, p->d, &t)) {
		p->failed = true;
		return false;
	}
	p->prev = t;
	if (t.kind == LTK_STRING) {
		value v;
		if (!lang_decode_string(p, &t, &v))
			return false;
		name = v.str;
	} else {
		const symbol *s = t.kind == LTK_IDENT ? lang_lookup(p, t.text, t.len) : NULL;
		if (!s || s->val.kind != VAL_STRING) {
			char found[300];
			return lang_error(p, t.loc, "expected a string after '#include', found %s",
					  s ? lang_value_kind_name(&s->val) : lang_describe(&t, found, sizeof found));
		}
		name = s->val.str;
	}
	diag_loc nloc = p->prev.loc;
	if (p->n_files - p->n_macro_calls > LANG_MAX_INCLUDE_DEPTH) {
		lang_error(p, at, "includes nested too deeply (limit is %d)", LANG_MAX_INCLUDE_DEPTH);
		note_chain(p);
		return false;
	}
	const char *cur = p->files[p->n_files - 1].path;
	const char *slash = strrchr(cur, '/');
	size_t n_dirs = 1 + p->opt.n_include_dirs;
	for (size_t i = 0; i < n_dirs; i++) {
		char *path;
		if (name[0] == '/')
			path = arena_strdup(&p->sc->arena, name);
		else if (i == 0)
			path = slash ? join_path(p, cur, (size_t)(slash - cur), name) : arena_strdup(&p->sc->arena, name);
		else
			path = join_path(p, p->opt.include_dirs[i - 1], strlen(p->opt.include_dirs[i - 1]), name);
		if (!path)
			return no_memory(p, at);
		for (int k = 0; k < p->n_files; k++)
			if (!strcmp(p->files[k].path, path)) {
				lang_error(p, nloc, "include cycle: '%s' is already being read", path);
				note_chain(p);
				return false;
			}
		const diag_source *src;
		int err = open_source(p, path, &src);
		if (err == 0)
			return push_file(p, src, path, at);
		if (err == ENOMEM)
			return no_memory(p, at);
		if (err != ENOENT)
			return lang_error(p, nloc, "cannot read include file '%s': %s", path, strerror(err));
		if (name[0] == '/')
			break;
	}
	return lang_error(p, nloc, "cannot find include file '%s' (searched the including file's folder%s)", name,
			  p->opt.n_include_dirs ? " and the -I folders" : "");
}

/* ---- symbols ----------------------------------------------------------------------------- */

/* The variable a by-reference parameter stands for (itself for any other symbol). */
static symbol *target(parser *p, symbol *s)
{
	if (s->ref > 0 && (size_t)s->ref <= p->globals.len)
		return &VECBUF_AT(&p->globals, symbol, (size_t)s->ref - 1);
	if (s->ref < 0 && (size_t)-s->ref <= p->locals.len)
		return &VECBUF_AT(&p->locals, symbol, (size_t)-s->ref - 1);
	return s;
}

/* The ref that names s (a symbol in one of the tables). */
static long ref_of(parser *p, const symbol *s)
{
	const symbol *g = p->globals.data, *l = p->locals.data;
	if (l && s >= l && s < l + p->locals.len)
		return -(long)(s - l) - 1;
	return (long)(s - g) + 1;
}

const symbol *lang_lookup(parser *p, const char *name, size_t len)
{
	for (size_t i = p->locals.len; i-- > 0;) {
		symbol *s = &VECBUF_AT(&p->locals, symbol, i);
		if (strlen(s->name) == len && !memcmp(s->name, name, len))
			return target(p, s);
	}
	for (size_t i = p->globals.len; i-- > 0;) {
		const symbol *s = &VECBUF_AT(&p->globals, symbol, i);
		if (strlen(s->name) == len && !memcmp(s->name, name, len))
			return s;
	}
	return NULL;
}

/* A parameter of the macro call of frame `depth` with this name, or NULL. */
static symbol *parameter(parser *p, int depth, const lang_token *name)
{
	if (!p->files[depth].macro)
		return NULL;
	for (size_t i = p->locals.len; i-- > 0;) {
		symbol *s = &VECBUF_AT(&p->locals, symbol, i);
		if (s->depth != depth)
			break;
		if (s->param && strlen(s->name) == name->len && !memcmp(s->name, name->text, name->len))
			return s;
	}
	return NULL;
}

/* #declare assigns the global; #local the current include file's scope (the main file's #local is
 * global, as in POV-Ray). As POV-Ray 3.7, #declare (as #local) of a parameter assigns the
 * parameter: the caller's variable when it was passed by reference. */
static bool define_in(parser *p, int frame, const lang_token *name, bool local, const value *v)
{
	symbol *param = parameter(p, frame, name);
	if (param) {
		target(p, param)->val = *v;
		return true;
	}
	deprecation dep = p->pending_dep;
	p->pending_dep = (deprecation){0};
	/* As povray 3.7.0's Parse_Declare: #declare of a name visible as a local (of this macro call
	 * or include file, or one enclosing it) assigns that local; only a name found nowhere or
	 * as a global is the global's. */
	for (size_t i = p->locals.len; !local && i-- > 0;) {
		symbol *s = &VECBUF_AT(&p->locals, symbol, i);
		if (s->depth > frame) /* a deeper frame's, still open (see decl_target.frame) */
			continue;
		if (strlen(s->name) == name->len && !memcmp(s->name, name->text, name->len)) {
			symbol *t = s->param ? target(p, s) : s;
			t->val = *v;
			if (dep.on)
				t->dep = dep;
			return true;
		}
	}
	int depth = local ? frame : 0;
	vecbuf *tab = depth ? &p->locals : &p->globals;
	/* The scope's symbols end at `at`: past it lie those of deeper frames still open (a macro
	 * whose body gave the value), which pop_scope removes from the end. */
	size_t at = tab->len;
	while (depth && at > 0 && VECBUF_AT(tab, symbol, at - 1).depth > depth)
		at--;
	for (size_t i = at; i-- > 0;) {
		symbol *s = &VECBUF_AT(tab, symbol, i);
		if (s->depth != depth)
			break;
		if (strlen(s->name) == name->len && !memcmp(s->name, name->text, name->len)) {
			s->val = *v;
			if (dep.on) /* as POV-Ray 3.7: a name stays deprecated when declared again */
				s->dep = dep;
			return true;
		}
	}
	symbol s = {arena_strndup(&p->sc->arena, name->text, name->len), depth, name->loc, *v, false, 0, dep};
	if (!s.name || !vecbuf_push(tab, &s))
		return no_memory(p, name->loc);
	if (at < tab->len - 1) { /* before the deeper frames' symbols; their references follow them */
		memmove(&VECBUF_AT(tab, symbol, at + 1), &VECBUF_AT(tab, symbol, at), (tab->len - 1 - at) * sizeof s);
		VECBUF_AT(tab, symbol, at) = s;
		for (size_t i = 0; i < tab->len; i++) {
			symbol *r = &VECBUF_AT(tab, symbol, i);
			if (r->ref < 0 && (size_t)(-r->ref - 1) >= at)
				r->ref--;
		}
	}
	return true;
}

/* define_in at the running frame. */
static bool define(parser *p, const lang_token *name, bool local, const value *v)
{
	return define_in(p, p->n_files - 1, name, local, v);
}

bool lang_define(parser *p, const lang_token *name, bool local, const value *v) { return define(p, name, local, v); }

static void pop_scope(parser *p, int depth)
{
	while (p->locals.len && VECBUF_AT(&p->locals, symbol, p->locals.len - 1).depth >= depth)
		p->locals.len--;
}

/* ---- directives -------------------------------------------------------------------------- */

/* deprecation = "deprecated" [ "once" ] [ string ]   (the lookahead is 'deprecated'; names are
 * not expanded) */
static bool deprecation_of(parser *p, deprecation *d)
{
	lang_advance(p);
	*d = (deprecation){.on = true, .once = lang_accept(p, LTK_KW_ONCE)};
	if (lang_peek(p)->kind == LTK_STRING) {
		value v;
		lang_token s = *lang_advance(p);
		if (!lang_decode_string(p, &s, &v))
			return false;
		d->msg = v.str;
	}
	return true;
}

/* A use of a name declared deprecated: POV-Ray 3.7's warning, at each use or the first (once). */
static void warn_deprecated(parser *p, const lang_token *t, const symbol *s)
{
	deprecation *d = (deprecation *)&s->dep; /* the symbol tables are the parser's own */
	if (d->once && d->warned)
		return;
	d->warned = true;
	if (d->msg)
		diag_warning(p->d, t->loc, "%s", d->msg);
	else
		diag_warning(p->d, t->loc, "identifier '%.*s' was declared deprecated", (int)t->len, t->text);
}

/* As POV-Ray 3.7: only a float, vector or colour value needs its ';', and only from language
 * version 3.5 on (`#declare Font = "cyrvetic.ttf"` has none in POV-Ray's samples). */
static bool semi_optional(parser *p, const value *v)
{
	bool numeric = v->kind == VAL_FLOAT || v->kind == VAL_VECTOR || v->kind == VAL_COLOR;
	if (numeric && p->version < 3.5) /* povray 3.7.0 warns too ("Possible Parse Error") */
		diag_warning(p->d, lang_peek(p)->loc, "a float, vector or colour #declare without ';' (accepted below "
						      "#version 3.5)");
	return !numeric || p->version < 3.5;
}

/* The lookahead read past a #declare's value without ';' is given back to the token stream
 * (fetch), after the name is defined: a directive there then runs, in order. An end of file is
 * dropped instead: the lexer meets it again and closes its file properly. */
static void hold_lookahead(parser *p)
{
	if (!p->have_tok)
		return;
	p->have_tok = false;
	if (p->tok.kind == LTK_EOF)
		return;
	p->held = p->tok;
	p->has_held = true;
}

/* True when the lookahead starts a value POV-Ray reads without operators: a string, a string
 * function's call, a name declared as a string or an array. Its #declare needs no ';', and is
 * read without a lookahead past it (`#declare C = ""` then a macro call that reads C). */
static bool lone_value(parser *p)
{
	lang_token *t = lang_peek(p);
	lang_tok after = t->kind == LTK_STRING || t->kind == LTK_IDENT ? lang_raw_next(p) : LTK_EOF;
	bool operand = after == LTK_PLUS || after == LTK_MINUS || after == LTK_STAR || after == LTK_SLASH ||
		       after == LTK_DOT || after == LTK_LBRACKET || after == LTK_LT || after == LTK_GT ||
		       after == LTK_LE || after == LTK_GE || after == LTK_EQ || after == LTK_NE || after == LTK_AMP ||
		       after == LTK_BAR || after == LTK_QUESTION;
	if (operand) /* "a" + 1: the expression's own error */
		return false;
	switch (t->kind) {
	case LTK_STRING:
	case LTK_KW_CONCAT:
	case LTK_KW_STR:
	case LTK_KW_VSTR:
	case LTK_KW_CHR:
	case LTK_KW_SUBSTR:
	case LTK_KW_STRUPR:
	case LTK_KW_STRLWR:
	case LTK_KW_DATETIME: return true;
	case LTK_IDENT: {
		const symbol *s = lang_lookup(p, t->text, t->len);
		return s && (s->val.kind == VAL_STRING || s->val.kind == VAL_ARRAY);
	}
	default: return false;
	}
}

/* `#declare A[i]...`: the array A names (declared) and the element's index. */
bool lang_element_target(parser *p, const lang_token *name, lang_array **arr, size_t *index)
{
	const symbol *s = lang_lookup(p, name->text, name->len);
	if (!s)
		return lang_error(p, name->loc, "cannot assign an element of '%.*s': it is not declared", (int)name->len,
				  name->text);
	if (s->val.kind != VAL_ARRAY)
		return lang_error(p, name->loc, "cannot assign an element of '%.*s': it is %s, not an array",
				  (int)name->len, name->text, lang_value_kind_name(&s->val));
	char nm[LANG_MAX_IDENT + 1];
	snprintf(nm, sizeof nm, "%.*s", (int)name->len, name->text);
	*arr = s->val.arr;
	return lang_array_index(p, arr, nm, index);
}

/* What a #declare assigns: a name (global, or local for #local) or an array's element. */
typedef struct decl_target {
	lang_token name;
	bool local;
	/* the frame of the #declare or #local: the one it defines in. A block value that a macro call
	 * gives (`#local M = Matrix_Trans(...)`) ends at the block's '}' while the called macro's
	 * frame is still open, as nothing is read past it. */
	int frame;
	lang_array *arr; /* an element's array, or NULL */
	size_t index;
	diag_loc at; /* the value, for an element's kind error */
} decl_target;

/* Stores a #declare's value: in the array element when arr is set, else in the name, which
 * takes the #declare's deprecation. An array taken from another (not fresh) is copied, as
 * POV-Ray does. */
static bool assign(parser *p, const decl_target *tg, value *v, bool fresh, deprecation dep)
{
	if (v->kind == VAL_ARRAY && !fresh && !lang_array_copy(p, tg->name.loc, v))
		return false;
	if (tg->arr)
		return lang_array_store(p, tg->at, tg->arr, tg->index, v);
	p->pending_dep = dep;
	return define_in(p, tg->frame, &tg->name, tg->local, v);
}

/* The value after '=': a block or array (';' optional), a lone string or array (';' optional, no
 * lookahead past it), or an expression and its ';' (optional but for numbers: semi_optional;
 * the lookahead read in its place is held for after the name is defined). */
static bool declare_value(parser *p, const decl_target *tg, deprecation dep)
{
	value v;
	bool handled = false;
	lang_tok k = lang_peek(p)->kind;
	if (k == LTK_KW_ARRAY || k == LTK_KW_FUNCTION || k == LTK_KW_SPLINE) {
		if (!(k == LTK_KW_ARRAY ? lang_array_value(p, &v) : lang_func_value(p, tg->arr ? NULL : &tg->name, &v)))
			return false;
		handled = true;
	} else if (!lang_declare_block(p, &v, &handled)) {
		return false;
	}
	if (handled) {
		if (!assign(p, tg, &v, true, dep))
			return false;
		lang_skip_optional_semi(p);
		return true;
	}
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	if (lone_value(p)) { /* no lookahead past it: what follows may be a macro call using the name */
		bool ok = lang_primary(p, &v);
		p->directive_expr = false;
		if (ok && lang_raw_next(p) == LTK_SEMI)
			lang_advance(p);
		return ok && assign(p, tg, &v, false, dep);
	}
	bool ok = lang_expr(p, &v), semi = false;
	if (ok) {
		semi = lang_accept(p, LTK_SEMI);
		if (!semi && !semi_optional(p, &v))
			ok = lang_error_found(p, "expected ';' after the value of '%.*s' (a float, vector or colour "
						 "needs it from #version 3.5 on)",
					      (int)tg->name.len, tg->name.text);
	}
	p->directive_expr = false;
	ok = ok && assign(p, tg, &v, false, dep);
	if (ok && !semi)
		hold_lookahead(p);
	return ok;
}

/* declare = ("#declare" | "#local") identifier [ index ] "=" ( block_value [";"] | array [";"]
 *         | expression ";" ) */
static bool do_declare(parser *p, const lang_token *dir)
{
	bool local = dir->kind == LTK_DIR_LOCAL;
	const char *dname = local ? "#local" : "#declare";
	int frame = p->n_files - 1;
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	p->no_expand = true;
	lang_token *t = lang_peek(p);
	deprecation dep = {0};
	if (t->kind == LTK_KW_DEPRECATED) {
		if (!deprecation_of(p, &dep)) {
			p->no_expand = false;
			return false;
		}
		t = lang_peek(p);
	}
	p->no_expand = false;
	if (t->kind != LTK_IDENT) {
		p->directive_expr = false;
		if (t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE)
			return lang_error(p, t->loc, "cannot %s '%.*s': it is a keyword", dname, (int)t->len, t->text);
		return lang_error_found(p, "expected an identifier after '%s'", dname);
	}
	decl_target tg = {.name = *lang_advance(p), .local = local, .frame = frame};
	if (lang_peek(p)->kind == LTK_LBRACKET && !lang_element_target(p, &tg.name, &tg.arr, &tg.index)) {
		p->directive_expr = false;
		return false;
	}
	const symbol *old = lang_lookup(p, tg.name.text, tg.name.len);
	if (old && old->dep.on)
		warn_deprecated(p, &tg.name, old);
	if (!lang_expect(p, LTK_EQ, "after the name in #declare")) {
		p->directive_expr = false;
		return false;
	}
	p->directive_expr = false;
	tg.at = lang_peek(p)->loc;
	return declare_value(p, &tg, dep);
}

/* "(" float ")" of a directive; what: "after '#if'". */
static bool paren_float(parser *p, const char *what, const char *role, double *v)
{
	*v = 0;
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	char after[64];
	snprintf(after, sizeof after, "after the %s", role);
	char as[64];
	snprintf(as, sizeof as, "as the %s", role);
	bool ok = lang_expect(p, LTK_LPAREN, what) && lang_float_expr(p, as, v) && lang_expect(p, LTK_RPAREN, after);
	p->directive_expr = false;
	return ok;
}

static bool cond_expr(parser *p, const char *what, bool *truth)
{
	double v;
	bool ok = paren_float(p, what, "condition", &v);
	*truth = lang_truth(v); /* POV-Ray: fabs(Value) > EPSILON */
	return ok;
}

/* The name of an #if-like directive token for messages: "#if", "#ifdef", "#ifndef". */
static const char *if_name(lang_tok k)
{
	return k == LTK_DIR_IFDEF ? "#ifdef" : k == LTK_DIR_IFNDEF ? "#ifndef" : "#if";
}

static bool second_else(parser *p, diag_loc at, const char *what, diag_loc if_loc, diag_loc first_else)
{
	return lang_error(p, at, "a second '#else' for the '%s' at line %u (the first '#else' is at line %u)",
			  what, if_loc.line, first_else.line);
}

static bool elseif_after_else(parser *p, diag_loc at, const char *what, diag_loc if_loc)
{
	return lang_error(p, at, "'#elseif' after the '#else' of the '%s' at line %u", what, if_loc.line);
}

/* What a skip is looking for at its own level (not inside the blocks nested in it). */
typedef enum skip_kind {
	SKIP_THEN, /* a false #if's branch: up to its #elseif, #else or #end */
	SKIP_ELSE, /* the rest of an #if after the branch that ran: up to #end; an #elseif after its
		      #else, or a second #else, is an error (first_else: the #else, if one began it) */
	SKIP_WHILE, /* a false #while's body: up to #end; #else is an error */
	SKIP_CASE, /* a #switch's case that does not match: up to its next #case, #range, #else or #end */
	SKIP_TO_END /* after #break: up to #end, past #else, #case and #range */
} skip_kind;

/* A block opened inside a skipped one: an #if remembers its first #else (line 0: none yet). */
typedef struct skipped_block {
	diag_loc open, else_at;
	bool is_if;
	const char *what; /* is_if: "#if", "#ifdef" or "#ifndef" */
} skipped_block;

/* At an #else inside a skipped branch, in the block nested innermost: a second #else of an #if is
 * an error there too, as at the skip's own level. */
static bool skipped_else(parser *p, skipped_block *b, diag_loc at)
{
	if (!b->is_if)
		return true;
	if (b->else_at.line)
		return second_else(p, at, b->what, b->open, b->else_at);
	b->else_at = at;
	return true;
}

/* Skips raw tokens up to the #else (SKIP_THEN only) or #end that closes the block opened at open
 * (for SKIP_CASE also its #case and #range); *stop, when not NULL, receives the directive that ended
 * the skip.
 * first_else: for SKIP_ELSE, the #else that began the skipped branch. Every block directive
 * (#if, #ifdef, #ifndef, #while, #for, #switch and POV-Ray's #macro) nests a level, and counts
 * toward the LANG_MAX_DEPTH open at once with the skipped block and the running ones. */
static bool skip_block(parser *p, diag_loc open, skip_kind kind, const char *what, diag_loc first_else,
		       lang_token *stop)
{
	lang_lexer *lx = &p->files[p->n_files - 1].lx;
	skipped_block nested[LANG_MAX_DEPTH];
	int level = 0, room = LANG_MAX_DEPTH - 1 - p->n_conds;
	lang_token t;
	if (!stop)
		stop = &t;
	for (;;) {
		p->skip_stop_at = lx->p;
		if (!lex(p, lx, p->d, &t)) {
			p->failed = true;
			return false;
		}
		bool is_if = t.kind == LTK_DIR_IF || t.kind == LTK_DIR_IFDEF || t.kind == LTK_DIR_IFNDEF;
		bool opens = is_if || t.kind == LTK_DIR_WHILE || t.kind == LTK_DIR_FOR || t.kind == LTK_DIR_SWITCH ||
			     t.kind == LTK_DIR_MACRO;
		if (opens) {
			if (level >= room)
				return nesting_too_deep(p, t.loc);
			nested[level++] = (skipped_block){t.loc, diag_noloc(), is_if, if_name(t.kind)};
			continue;
		}
		switch (t.kind) {
		case LTK_EOF:
			lang_error(p, t.loc, "'#end' expected (to close '%s' at line %u), found end of file", what, open.line);
			note(p, open, "'%s' opened here", what);
			return false;
		case LTK_DIR_ELSEIF:
			if (level > 0 || kind == SKIP_TO_END)
				break;
			if (kind == SKIP_THEN) {
				*stop = t;
				return true;
			}
			if (kind == SKIP_ELSE && first_else.line)
				return elseif_after_else(p, t.loc, what, open);
			if (kind == SKIP_ELSE)
				break;
			return lang_error(p, t.loc, "'#elseif' without '#if'");
		case LTK_DIR_ELSE:
			if (level > 0) {
				if (!skipped_else(p, &nested[level - 1], t.loc))
					return false;
				break;
			}
			if (kind == SKIP_THEN || kind == SKIP_CASE) {
				*stop = t;
				return true;
			}
			if (kind == SKIP_TO_END)
				break;
			if (kind == SKIP_WHILE)
				return lang_error(p, t.loc, "'#else' without '#if'");
			if (first_else.line)
				return second_else(p, t.loc, what, open, first_else);
			first_else = t.loc; /* the #else after an #elseif's taken branch */
			break;
		case LTK_DIR_CASE:
		case LTK_DIR_RANGE:
			if (level == 0 && kind == SKIP_CASE) {
				*stop = t;
				return true;
			}
			break;
		case LTK_DIR_END:
			if (level-- == 0) {
				*stop = t;
				return true;
			}
			break;
		default:
			break;
		}
	}
}

static bool push_cond(parser *p, cond_kind kind, diag_loc loc, const char *what)
{
	if (p->n_conds >= LANG_MAX_DEPTH)
		return nesting_too_deep(p, loc);
	cond *c = &p->conds[p->n_conds++];
	c->kind = kind;
	c->loc = loc;
	c->what = what;
	c->file = p->n_files - 1;
	c->iterations = 0;
	return true;
}

/* Runs the branch chosen by truth of the #if (or #ifdef, #ifndef) at loc, skipping the other. */
static bool branch(parser *p, diag_loc loc, const char *what, bool truth)
{
	lang_token stop;
	for (;;) {
		if (truth)
			return push_cond(p, COND_IF, loc, what);
		if (!skip_block(p, loc, SKIP_THEN, what, diag_noloc(), &stop))
			return false;
		if (stop.kind != LTK_DIR_ELSEIF)
			break;
		if (!cond_expr(p, "after '#elseif'", &truth))
			return false;
	}
	if (stop.kind == LTK_DIR_END)
		return true;
	if (!push_cond(p, COND_ELSE, loc, what))
		return false;
	p->conds[p->n_conds - 1].else_loc = stop.loc;
	return true;
}

/* if = "#if" "(" expression ")" { token } [ "#else" { token } ] "#end" */
static bool do_if(parser *p, diag_loc loc)
{
	bool truth;
	return cond_expr(p, "after '#if'", &truth) && branch(p, loc, "#if", truth);
}

/* The name a directive takes (#ifdef's, #undef's): an identifier, or a word of the language or of
 * POV-Ray, which is never declared. *sym: its symbol, or NULL. */
static bool directive_name(parser *p, const char *dname, lang_token *name, const symbol **sym)
{
	p->no_expand = true;
	lang_token *t = lang_peek(p);
	p->no_expand = false;
	bool word = t->kind == LTK_IDENT || t->kind == LTK_UNSUPPORTED ||
		    (t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE);
	if (!word)
		return lang_error_found(p, "expected an identifier after '%s'", dname);
	*name = *lang_advance(p);
	*sym = name->kind == LTK_IDENT ? lang_lookup(p, name->text, name->len) : NULL;
	return true;
}

/* Removes the innermost declaration of the name (as lang_lookup finds it: locals first). */
static void forget(parser *p, const char *name, size_t len)
{
	vecbuf *tabs[] = {&p->locals, &p->globals};
	for (int k = 0; k < 2; k++) {
		symbol *base = tabs[k]->data;
		for (size_t i = tabs[k]->len; i-- > 0;)
			if (strlen(base[i].name) == len && !memcmp(base[i].name, name, len)) {
				memmove(base + i, base + i + 1, (tabs[k]->len - i - 1) * sizeof *base);
				tabs[k]->len--;
				return;
			}
	}
}

void lang_forget(parser *p, const char *name, size_t len) { forget(p, name, len); }

/* ifdef = ( "#ifdef" | "#ifndef" ) "(" identifier [ index ] ")" { token } [ "#else" { token } ] "#end"
 * As POV-Ray 3.7's Parse_Ifdef_Param: true when the name is declared (a keyword never is), or
 * the array's element assigned. */
static bool do_ifdef(parser *p, diag_loc loc, bool want_defined)
{
	const char *dname = want_defined ? "#ifdef" : "#ifndef";
	char ctx[32];
	snprintf(ctx, sizeof ctx, "after '%s'", dname);
	lang_token name;
	const symbol *s = NULL;
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	bool ok = lang_expect(p, LTK_LPAREN, ctx) && directive_name(p, dname, &name, &s);
	bool is = s != NULL;
	if (ok && lang_peek(p)->kind == LTK_LBRACKET) {
		size_t i;
		lang_array *a = s ? s->val.arr : NULL;
		char nm[LANG_MAX_IDENT + 1];
		snprintf(nm, sizeof nm, "%.*s", (int)name.len, name.text);
		if (!s || s->val.kind != VAL_ARRAY)
			ok = lang_error(p, name.loc, "'%s' of an element of '%s', which is %s, not an array", dname, nm,
					s ? lang_value_kind_name(&s->val) : "not declared");
		else if ((ok = lang_array_index(p, &a, nm, &i)))
			is = a->set[i];
	}
	ok = ok && lang_expect(p, LTK_RPAREN, "after the identifier");
	p->directive_expr = false;
	return ok && branch(p, loc, dname, is == want_defined);
}

/* undef = "#undef" identifier. Forgets the innermost declaration of the name; an unknown name is a
 * warning, as in POV-Ray 3.7. */
static bool do_undef(parser *p)
{
	lang_token name;
	const symbol *s = NULL;
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	bool ok = directive_name(p, "#undef", &name, &s);
	p->directive_expr = false;
	if (!ok)
		return false;
	if (!s) {
		diag_warning(p->d, name.loc, "'#undef' of '%.*s', which is not declared", (int)name.len, name.text);
		return true;
	}
	if (s->dep.on)
		warn_deprecated(p, &name, s);
	forget(p, name.text, name.len);
	return true;
}

static bool do_else(parser *p, diag_loc loc)
{
	if (p->n_conds > p->files[p->n_files - 1].cond_base && p->conds[p->n_conds - 1].kind == COND_SWITCH)
		return true; /* a case that ran on without #break: on into the #else, as in POV-Ray */
	if (p->n_conds <= p->files[p->n_files - 1].cond_base || p->conds[p->n_conds - 1].kind == COND_WHILE ||
	    p->conds[p->n_conds - 1].kind == COND_FOR)
		return lang_error(p, loc, "'#else' without '#if'");
	cond c = p->conds[--p->n_conds];
	if (c.kind == COND_ELSE)
		return second_else(p, loc, c.what, c.loc, c.else_loc);
	return skip_block(p, c.loc, SKIP_ELSE, c.what, loc, NULL);
}

/* elseif = "#elseif" "(" expression ")": met where a branch of an #if ran, it ends the #if's
 * running part: the rest is skipped to its #end, as POV-Ray 3.7 does. */
static bool do_elseif(parser *p, diag_loc loc)
{
	if (p->n_conds <= p->files[p->n_files - 1].cond_base ||
	    (p->conds[p->n_conds - 1].kind != COND_IF && p->conds[p->n_conds - 1].kind != COND_ELSE))
		return lang_error(p, loc, "'#elseif' without '#if'");
	cond c = p->conds[--p->n_conds];
	if (c.kind == COND_ELSE)
		return elseif_after_else(p, loc, c.what, c.loc);
	return skip_block(p, c.loc, SKIP_ELSE, c.what, diag_noloc(), NULL);
}

/* Counts an iteration that the loop c begins. The limits count iterations begun: a loop of
 * exactly max_loop_iterations runs, one more is refused (and so for the scene's total). */
static bool begin_iteration(parser *p, cond *c)
{
	long limit = p->opt.max_loop_iterations > 0 ? p->opt.max_loop_iterations : LANG_MAX_LOOP_ITERATIONS;
	if (++c->iterations > limit)
		return lang_error(p, c->loc, "%s loop runs too long (limit is %ld iterations)", c->what, limit);
	long total = p->opt.max_loop_iterations > 0 ? 10 * limit : DEFAULT_TOTAL_ITERATIONS;
	if (++p->total_iterations > total)
		return lang_error(p, c->loc, "too many loop iterations in this scene (limit is %ld in all)", total);
	return true;
}

/* while = "#while" "(" expression ")" { token } "#end" */
static bool do_while(parser *p, diag_loc loc)
{
	lang_lexer restart = p->files[p->n_files - 1].lx;
	bool truth;
	if (!cond_expr(p, "after '#while'", &truth))
		return false;
	if (!truth)
		return skip_block(p, loc, SKIP_WHILE, "#while", diag_noloc(), NULL);
	if (!push_cond(p, COND_WHILE, loc, "#while"))
		return false;
	p->conds[p->n_conds - 1].restart = restart;
	return begin_iteration(p, &p->conds[p->n_conds - 1]);
}

/* The loop variable of #for goes on while it has not passed the end (POV-Ray 3.7's
 * Parse_For_Param and its #end, with their tolerance). */
static const double FOR_EPSILON = 1e-10;

static bool for_goes_on(double v, double end, double step)
{
	return step > 0 ? v <= end + FOR_EPSILON : v >= end - FOR_EPSILON;
}

/* for = "#for" "(" identifier "," expression "," expression [ "," expression ] ")" { token } "#end"
 * As POV-Ray 3.7: the identifier is declared in the current scope (as by #local), takes the start
 * value, and the body runs while it has not passed the end, adding the step (default 1) at each
 * #end; a step of 0 is an error. */
static bool do_for(parser *p, diag_loc loc)
{
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	lang_token name;
	double start = 0, end = 0, step = 1;
	diag_loc step_loc = loc;
	bool ok = lang_expect(p, LTK_LPAREN, "after '#for'");
	if (ok && lang_peek(p)->kind != LTK_IDENT)
		ok = lang_error_found(p, "expected the loop variable's name after '#for ('");
	if (ok) {
		name = *lang_advance(p);
		ok = lang_expect(p, LTK_COMMA, "after the loop variable") && lang_float(p, "as the start", &start) &&
		     lang_expect(p, LTK_COMMA, "after the start") && lang_float(p, "as the end", &end);
	}
	if (ok && lang_accept(p, LTK_COMMA)) {
		step_loc = lang_peek(p)->loc;
		ok = lang_float(p, "as the step", &step);
	}
	ok = ok && lang_expect(p, LTK_RPAREN, "to close '#for ('");
	p->directive_expr = false;
	if (!ok)
		return false;
	if (fabs(step) < FOR_EPSILON)
		return lang_error(p, step_loc, "the step of '#for' must not be 0");
	value v = {.kind = VAL_FLOAT, .n = 1, .v = {start}};
	if (!define(p, &name, true, &v))
		return false;
	if (!for_goes_on(start, end, step))
		return skip_block(p, loc, SKIP_WHILE, "#for", diag_noloc(), NULL);
	if (!push_cond(p, COND_FOR, loc, "#for"))
		return false;
	cond *c = &p->conds[p->n_conds - 1];
	c->restart = p->files[p->n_files - 1].lx;
	c->var = arena_strndup(&p->sc->arena, name.text, name.len);
	c->end = end, c->step = step;
	if (!c->var)
		return no_memory(p, loc);
	return begin_iteration(p, c);
}

/* At a #for's #end: the step added, one more iteration while the variable has not passed the end. */
static bool end_for(parser *p, cond *c, diag_loc at)
{
	symbol *s = (symbol *)lang_lookup(p, c->var, strlen(c->var));
	if (!s || s->val.kind != VAL_FLOAT)
		return lang_error(p, at, "the loop variable '%s' of the '#for' at line %u must stay a float (it is %s)",
				  c->var, c->loc.line, s ? lang_value_kind_name(&s->val) : "undeclared");
	s->val.v[0] += c->step;
	if (!for_goes_on(s->val.v[0], c->end, c->step)) {
		p->n_conds--;
		return true;
	}
	p->files[p->n_files - 1].lx = c->restart;
	return begin_iteration(p, c);
}

/* At a #while's #end: one more iteration when the condition still holds. */
static bool do_end(parser *p, diag_loc loc)
{
	if (p->n_conds <= p->files[p->n_files - 1].cond_base)
		return lang_error(p, loc, "'#end' without '#if' or '#while'");
	cond *c = &p->conds[p->n_conds - 1];
	if (c->kind == COND_FOR)
		return end_for(p, c, loc);
	if (c->kind != COND_WHILE) {
		p->n_conds--;
		return true;
	}
	lang_lexer *lx = &p->files[p->n_files - 1].lx;
	lang_lexer after_end = *lx;
	*lx = c->restart;
	bool truth;
	if (!cond_expr(p, "after '#while'", &truth))
		return false;
	if (!truth) {
		*lx = after_end;
		p->n_conds--;
		return true;
	}
	return begin_iteration(p, c);
}

/* The tolerance of #case, as POV-Ray 3.7's (EPSILON, configbackend.h). */
static const double CASE_EPSILON = 1e-10;

/* case = "#case" "(" expression ")" ; range = "#range" "(" expression "," expression ")".
 * *match: the switch value v equals the case's (within CASE_EPSILON) or lies in the range. */
static bool case_matches(parser *p, const lang_token *t, double v, bool *match)
{
	if (t->kind == LTK_DIR_CASE) {
		double x;
		if (!paren_float(p, "after '#case'", "case value", &x))
			return false;
		*match = fabs(x - v) < CASE_EPSILON;
		return true;
	}
	double lo = 0, hi = 0;
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	bool ok = lang_expect(p, LTK_LPAREN, "after '#range'") && lang_float(p, "as the range's low end", &lo) &&
		  lang_expect(p, LTK_COMMA, "after the range's low end") &&
		  lang_float(p, "as the range's high end", &hi) && lang_expect(p, LTK_RPAREN, "after the range");
	p->directive_expr = false;
	*match = v >= lo && v <= hi;
	return ok;
}

/* From the #case, #range, #else or #end t of the #switch at loc on: runs the first case that
 * matches v (and, without #break, what follows it), or the #else, or nothing. */
static bool select_case(parser *p, diag_loc loc, double v, lang_token t)
{
	for (;;) {
		if (t.kind == LTK_DIR_END)
			return true;
		bool match = t.kind == LTK_DIR_ELSE;
		if (!match && !case_matches(p, &t, v, &match))
			return false;
		if (match) {
			if (!push_cond(p, COND_SWITCH, loc, "#switch"))
				return false;
			p->conds[p->n_conds - 1].value = v;
			return true;
		}
		if (!skip_block(p, loc, SKIP_CASE, "#switch", diag_noloc(), &t))
			return false;
	}
}

/* switch = "#switch" "(" expression ")" { ( case | range ) { token } } [ "#else" { token } ] "#end"
 * As POV-Ray 3.7: the first #case or #range that matches runs up to #break or the #end, on
 * through the later #case, #range and #else; none matching runs the #else. */
static bool do_switch(parser *p, diag_loc loc)
{
	double v;
	if (!paren_float(p, "after '#switch'", "switch value", &v))
		return false;
	lang_token t;
	if (!lex(p, &p->files[p->n_files - 1].lx, p->d, &t)) {
		p->failed = true;
		return false;
	}
	if (t.kind != LTK_DIR_CASE && t.kind != LTK_DIR_RANGE) {
		char found[300];
		return lang_error(p, t.loc, "'#switch' must be followed by '#case' or '#range', found %s",
				  lang_describe(&t, found, sizeof found));
	}
	return select_case(p, loc, v, t);
}

/* A #case or #range met while a case runs: the case falls through; its operands are read. */
static bool do_case(parser *p, const lang_token *t)
{
	if (p->n_conds <= p->files[p->n_files - 1].cond_base || p->conds[p->n_conds - 1].kind != COND_SWITCH)
		return lang_error(p, t->loc, "'%s' outside '#switch'", t->kind == LTK_DIR_CASE ? "#case" : "#range");
	bool match;
	return case_matches(p, t, p->conds[p->n_conds - 1].value, &match);
}

/* #break leaves the innermost #switch, #while or #for (POV-Ray 3.7's Break): the blocks open
 * inside it are skipped to their #end, then it is. */
static bool do_break(parser *p, diag_loc loc)
{
	int base = p->files[p->n_files - 1].cond_base, k = p->n_conds - 1;
	while (k >= base && p->conds[k].kind != COND_SWITCH && p->conds[k].kind != COND_WHILE &&
	       p->conds[k].kind != COND_FOR)
		k--;
	if (k < base)
		return lang_error(p, loc, "'#break' outside '#switch', '#while' or '#for'");
	while (p->n_conds > k) {
		cond *c = &p->conds[p->n_conds - 1];
		if (!skip_block(p, c->loc, SKIP_TO_END, c->what, diag_noloc(), NULL))
			return false;
		p->n_conds--;
	}
	return true;
}

/* version = "#version" expression ";"   (sets what `version` reads) */
static bool do_version(parser *p)
{
	double v;
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	bool ok = lang_float(p, "after '#version'", &v) && lang_expect(p, LTK_SEMI, "after the #version number");
	p->directive_expr = false;
	if (ok)
		p->version = v;
	return ok;
}

/* The end of a file: its conditionals must be closed; its #local names die. */
static bool end_of_file(parser *p, const lang_token *t)
{
	include_frame *f = &p->files[p->n_files - 1];
	if (p->n_conds > f->cond_base) {
		cond *c = &p->conds[p->n_conds - 1];
		const char *what = c->what;
		lang_error(p, t->loc, "'#end' expected (to close '%s' at line %u), found end of file", what, c->loc.line);
		note(p, c->loc, "'%s' opened here", what);
		return false;
	}
	pop_scope(p, p->n_files - 1);
	if (f->macro) {
		p->n_macro_calls--;
		p->directive_expr = f->saved_directive_expr;
		p->directive_expr_at = f->saved_directive_expr_at;
	}
	if (p->n_files > 1)
		p->n_files--;
	else
		p->eof = *t, p->n_files = 0;
	return true;
}

/* The text of a #warning or #error as one line of a diagnostic: control characters (a "\n" at
 * its end, say) become spaces, and trailing blanks go. */
static const char *message_line(parser *p, const char *s)
{
	char *m = arena_strdup(&p->sc->arena, s);
	if (!m)
		return s;
	size_t n = strlen(m);
	for (size_t i = 0; i < n; i++)
		if ((unsigned char)m[i] < 0x20 || m[i] == 0x7f)
			m[i] = ' ';
	while (n > 0 && m[n - 1] == ' ')
		m[--n] = '\0';
	return m;
}

lang_tok lang_raw_next(parser *p)
{
	lang_lexer lx = p->files[p->n_files - 1].lx;
	lang_token t;
	diag quiet;
	diag_init(&quiet, NULL);
	return lex(p, &lx, &quiet, &t) ? t.kind : LTK_EOF;
}

/* The operand of #debug, #warning, #error: a string, a name declared as one, an array element or a
 * function call (concat, str, ...). One primary, as the directive has no terminator: reading on
 * for an operator would take the next directive as the lookahead. */
static bool message_text(parser *p, const char *what, const char **s)
{
	lang_token *t = lang_peek(p);
	bool call = t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE;
	if (t->kind == LTK_STRING || call || (t->kind == LTK_IDENT && lang_raw_next(p) == LTK_LBRACKET)) {
		diag_loc at = t->loc;
		value v;
		if (!lang_primary(p, &v))
			return false;
		if (v.kind != VAL_STRING)
			return lang_error(p, at, "expected a string %s, found %s", what, lang_value_kind_name(&v));
		*s = v.str;
		return true;
	}
	const symbol *sym = t->kind == LTK_IDENT ? lang_lookup(p, t->text, t->len) : NULL;
	if (sym && sym->val.kind == VAL_STRING) {
		lang_advance(p);
		*s = sym->val.str;
		return true;
	}
	if (sym)
		return lang_error(p, t->loc, "expected a string %s, found %s", what, lang_value_kind_name(&sym->val));
	if (t->kind == LTK_IDENT)
		return lang_error(p, t->loc, "undeclared identifier '%.*s'", (int)t->len, t->text);
	return lang_error_found(p, "expected a string %s", what);
}

/* message = ( "#debug" | "#warning" | "#error" ) ( string | identifier )
 * As POV-Ray 3.7: #debug writes the text as it is (its "\n" ends a line) to the diagnostics stream
 * (stderr); #warning reports it as a warning at the directive; #error stops the parse with it. */
static bool do_message(parser *p, const lang_token *dir)
{
	const char *dname = dir->kind == LTK_DIR_DEBUG ? "#debug" : dir->kind == LTK_DIR_WARNING ? "#warning" : "#error";
	char what[32];
	snprintf(what, sizeof what, "after '%s'", dname);
	const char *s = NULL;
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	bool ok = message_text(p, what, &s);
	p->directive_expr = false;
	if (!ok)
		return false;
	if (dir->kind == LTK_DIR_DEBUG) {
		if (p->d->out) {
			fputs(s, p->d->out);
			fflush(p->d->out);
		}
		return true;
	}
	if (dir->kind == LTK_DIR_WARNING) {
		diag_warning(p->d, dir->loc, "%s", message_line(p, s));
		return true;
	}
	return lang_error(p, dir->loc, "parse halted by #error: %s", message_line(p, s));
}

/* ---- macros ------------------------------------------------------------------------------ */

/* macro = "#macro" identifier "(" [ param { "," param } ] ")" { token } "#end"
 * param = [ "optional" ] identifier
 * The body is not run here: it is skipped to its #end (blocks nest in it) and kept as a span of
 * the source, lexed again at each call. A macro is global, as in POV-Ray 3.7. */
static bool do_macro(parser *p, diag_loc loc)
{
	lang_macro *m = arena_zalloc(&p->sc->arena, 1, sizeof *m);
	if (!m)
		return no_memory(p, loc);
	p->directive_expr = true, p->directive_expr_at = p->dir_frame;
	p->no_expand = true;
	lang_token name;
	bool ok = lang_peek(p)->kind == LTK_IDENT || lang_error_found(p, "expected the macro's name after '#macro'");
	if (ok) {
		name = *lang_advance(p);
		ok = lang_expect(p, LTK_LPAREN, "after the macro's name");
	}
	while (ok && !lang_accept(p, LTK_RPAREN)) {
		if (m->n_params && !lang_expect(p, LTK_COMMA, "between the macro's parameters")) {
			ok = false;
			break;
		}
		lang_token *t = lang_peek(p);
		bool optional = t->kind == LTK_IDENT && t->len == 8 && !memcmp(t->text, "optional", 8);
		if (optional)
			t = lang_advance(p), t = lang_peek(p);
		if (t->kind != LTK_IDENT) {
			ok = lang_error_found(p, "expected a parameter name in '#macro %.*s'", (int)name.len, name.text);
			break;
		}
		if (m->n_params == LANG_MAX_MACRO_PARAMS) {
			ok = lang_error(p, t->loc, "too many parameters (limit is %d)", LANG_MAX_MACRO_PARAMS);
			break;
		}
		m->params[m->n_params] = arena_strndup(&p->sc->arena, t->text, t->len);
		if (!m->params[m->n_params]) {
			ok = no_memory(p, t->loc);
			break;
		}
		m->optional[m->n_params++] = optional;
		lang_advance(p);
	}
	p->directive_expr = false;
	p->no_expand = false;
	if (!ok)
		return false;
	include_frame *f = &p->files[p->n_files - 1];
	m->name = arena_strndup(&p->sc->arena, name.text, name.len);
	m->loc = loc;
	m->body = f->lx;
	m->path = f->path;
	if (!m->name)
		return no_memory(p, loc);
	if (!skip_block(p, loc, SKIP_WHILE, "#macro", diag_noloc(), NULL))
		return false;
	m->body_end = p->skip_stop_at;
	value v = {.kind = VAL_MACRO, .mac = m};
	return define(p, &name, false, &v);
}

/* True when the identifier just peeked is followed by ',' or ')': a bare identifier argument. */
static bool bare_identifier(parser *p)
{
	lang_lexer lx = p->files[p->n_files - 1].lx;
	lang_token t;
	diag quiet;
	diag_init(&quiet, NULL);
	return lex(p, &lx, &quiet, &t) && (t.kind == LTK_COMMA || t.kind == LTK_RPAREN);
}

static bool wrong_arg_count(parser *p, diag_loc at, const lang_macro *m, int given)
{
	int needed = 0;
	for (int i = 0; i < m->n_params; i++)
		needed += !m->optional[i];
	if (needed == m->n_params)
		lang_error(p, at, "macro '%s' takes %d argument%s, %d given", m->name, m->n_params,
			   m->n_params == 1 ? "" : "s", given);
	else
		lang_error(p, at, "macro '%s' takes %d to %d arguments, %d given", m->name, needed, m->n_params, given);
	note(p, m->loc, "'%s' is defined here", m->name);
	return false;
}

/* One argument: *set false when it is omitted (an optional parameter stays undefined). A bare
 * identifier is passed by reference (*ref), anything else by value, as POV-Ray 3.7 documents. */
static bool argument(parser *p, const lang_macro *m, int i, value *v, long *ref, bool *set)
{
	lang_token *t = lang_peek(p);
	*ref = 0, *set = true;
	if (t->kind == LTK_COMMA || t->kind == LTK_RPAREN) {
		*set = false;
		if (m->optional[i])
			return true;
		return lang_error(p, t->loc, "missing argument for the parameter '%s' of macro '%s'", m->params[i], m->name);
	}
	if (t->kind == LTK_IDENT && bare_identifier(p)) {
		const symbol *s = lang_lookup(p, t->text, t->len);
		if (!s && m->optional[i]) {
			*set = false;
			lang_advance(p);
			return true;
		}
		if (s) {
			*ref = ref_of(p, s);
			*v = s->val;
			lang_advance(p);
			return true;
		}
	}
	if (t->kind == LTK_KW_FUNCTION || t->kind == LTK_KW_SPLINE)
		return lang_func_value(p, NULL, v);
	bool block = false; /* a block (transform { }, pigment { }, an object) is passed by value too */
	if (!lang_declare_block(p, v, &block))
		return false;
	return block || lang_expr(p, v);
}

/* call = identifier "(" [ argument { "," argument } ] ")", where identifier names a macro: the
 * arguments are evaluated in the caller's scope, then the body is read in place of the call, in a
 * frame of its own (its #local names and parameters die at its end). */
static bool invoke(parser *p, const lang_token *name, const lang_macro *m)
{
	if (p->n_macro_calls >= LANG_MAX_MACRO_DEPTH) {
		lang_error(p, name->loc, "macro calls nested too deeply calling '%s' (limit is %d)", m->name,
			   LANG_MAX_MACRO_DEPTH);
		note_chain(p);
		return false;
	}
	bool saved = p->directive_expr;
	int saved_at = p->directive_expr_at;
	p->directive_expr = true, p->directive_expr_at = p->n_files;
	value vals[LANG_MAX_MACRO_PARAMS];
	long refs[LANG_MAX_MACRO_PARAMS];
	bool set[LANG_MAX_MACRO_PARAMS];
	char ctx[300];
	snprintf(ctx, sizeof ctx, "after the macro name '%s'", m->name);
	bool ok = lang_expect(p, LTK_LPAREN, ctx);
	int n = 0;
	for (; ok && n < m->n_params; n++) {
		if (n > 0 && lang_peek(p)->kind == LTK_RPAREN)
			break;
		if (n > 0 && !lang_expect(p, LTK_COMMA, "between macro arguments"))
			ok = false;
		else
			ok = argument(p, m, n, &vals[n], &refs[n], &set[n]);
	}
	if (ok && (lang_peek(p)->kind == LTK_COMMA || (m->n_params == 0 && lang_peek(p)->kind != LTK_RPAREN)))
		ok = wrong_arg_count(p, lang_peek(p)->loc, m, n + 1);
	for (int i = n; ok && i < m->n_params; i++)
		if (!m->optional[i])
			ok = wrong_arg_count(p, lang_peek(p)->loc, m, n);
		else
			set[i] = false;
	ok = ok && lang_expect(p, LTK_RPAREN, "to close the macro's arguments");
	p->directive_expr = saved, p->directive_expr_at = saved_at;
	if (!ok)
		return false;
	if (p->n_files >= (int)(sizeof p->files / sizeof p->files[0]))
		return lang_error(p, name->loc, "includes and macro calls nested too deeply");
	include_frame *f = &p->files[p->n_files++];
	f->lx = m->body;
	f->lx.end = m->body_end;
	f->path = m->path;
	f->included_at = name->loc;
	f->cond_base = p->n_conds;
	f->released = m->body.p;
	f->macro = m;
	f->saved_directive_expr = saved;
	f->saved_directive_expr_at = saved_at;
	p->n_macro_calls++;
	p->directive_expr = false;
	for (int i = 0; i < m->n_params; i++) {
		if (!set[i])
			continue;
		symbol s = {m->params[i], p->n_files - 1, name->loc, vals[i], true, refs[i], {0}};
		if (!vecbuf_push(&p->locals, &s))
			return no_memory(p, name->loc);
	}
	return true;
}

/* Runs one directive. A directive reads its operands through the token stream, which may run
 * further directives inside it (`#declare X = #if ...`): each counts a level of LANG_MAX_DEPTH. */
static bool run_directive(parser *p, const lang_token *dir)
{
	if (!lang_enter(p, dir->loc))
		return false;
	int saved_frame = p->dir_frame;
	p->dir_frame = p->n_files;
	bool ok;
	switch (dir->kind) {
	case LTK_DIR_INCLUDE: ok = do_include(p, dir->loc); break;
	case LTK_DIR_DECLARE:
	case LTK_DIR_LOCAL: ok = do_declare(p, dir); break;
	case LTK_DIR_IF: ok = do_if(p, dir->loc); break;
	case LTK_DIR_ELSE: ok = do_else(p, dir->loc); break;
	case LTK_DIR_ELSEIF: ok = do_elseif(p, dir->loc); break;
	case LTK_DIR_END: ok = do_end(p, dir->loc); break;
	case LTK_DIR_WHILE: ok = do_while(p, dir->loc); break;
	case LTK_DIR_FOR: ok = do_for(p, dir->loc); break;
	case LTK_DIR_SWITCH: ok = do_switch(p, dir->loc); break;
	case LTK_DIR_CASE:
	case LTK_DIR_RANGE: ok = do_case(p, dir); break;
	case LTK_DIR_BREAK: ok = do_break(p, dir->loc); break;
	case LTK_DIR_IFDEF: ok = do_ifdef(p, dir->loc, true); break;
	case LTK_DIR_IFNDEF: ok = do_ifdef(p, dir->loc, false); break;
	case LTK_DIR_UNDEF: ok = do_undef(p); break;
	case LTK_DIR_MACRO: ok = do_macro(p, dir->loc); break;
	case LTK_DIR_DEFAULT: ok = lang_default(p); break;
	case LTK_DIR_FOPEN: ok = lang_fopen(p, dir->loc); break;
	case LTK_DIR_FCLOSE: ok = lang_fclose(p); break;
	case LTK_DIR_READ: ok = lang_read_directive(p, dir->loc); break;
	case LTK_DIR_WRITE: ok = lang_write_directive(p); break;
	case LTK_DIR_DEBUG:
	case LTK_DIR_WARNING:
	case LTK_DIR_ERROR: ok = do_message(p, dir); break;
	default: ok = do_version(p); break;
	}
	p->dir_frame = saved_frame;
	lang_leave(p);
	return ok;
}

/* The next token after running directives. */
static bool fetch(parser *p, lang_token *t)
{
	for (;;) {
		if (p->failed || p->n_files == 0) {
			*t = p->eof;
			return !p->failed;
		}
		if (p->has_held) { /* the token after a #declare without ';' (hold_lookahead) */
			p->has_held = false;
			*t = p->held;
			if (t->kind == LTK_UNSUPPORTED_DIRECTIVE) {
				report_unsupported(p, t);
				*t = p->eof;
				return false;
			}
			if (t->kind < LANG_FIRST_DIRECTIVE)
				return true;
			lang_token dir = *t;
			if (!run_directive(p, &dir)) {
				p->failed = true;
				*t = p->eof;
				return false;
			}
			continue;
		}
		include_frame *f = &p->files[p->n_files - 1];
		if (!lex(p, &f->lx, p->d, t)) {
			p->failed = true;
			p->eof.loc = t->loc;
			*t = p->eof;
			return false;
		}
		release_behind(f);
		if (t->kind == LTK_IDENT && !p->no_expand) {
			const symbol *s = lang_lookup(p, t->text, t->len);
			if (s && s->dep.on)
				warn_deprecated(p, t, s);
			if (s && s->val.kind == VAL_MACRO) {
				lang_token name = *t;
				if (!invoke(p, &name, s->val.mac)) {
					p->failed = true;
					*t = p->eof;
					return false;
				}
				continue;
			}
		}
		if (t->kind < LANG_FIRST_DIRECTIVE && t->kind != LTK_EOF && t->kind != LTK_UNSUPPORTED_DIRECTIVE)
			return true;
		if (t->kind == LTK_UNSUPPORTED_DIRECTIVE) {
			report_unsupported(p, t);
			*t = p->eof;
			return false;
		}
		if (t->kind == LTK_EOF) {
			if (p->n_files == 1 && p->directive_expr && p->directive_expr_at == 1)
				return true; /* a directive's expression met the end of the scene */
			if (!end_of_file(p, t))
				return false;
			continue;
		}
		if (p->directive_expr && p->directive_expr_at == p->n_files)
			return true; /* "expected ';' ..., found '#declare'" */
		lang_token dir = *t;
		if (!run_directive(p, &dir)) {
			p->failed = true;
			*t = p->eof;
			return false;
		}
	}
}

lang_token *lang_peek(parser *p)
{
	if (!p->have_tok) {
		lang_token t;
		fetch(p, &t);
		p->tok = t;
		p->have_tok = true;
	}
	return &p->tok;
}

lang_token *lang_advance(parser *p)
{
	lang_peek(p);
	p->prev = p->tok;
	p->have_tok = false;
	return &p->prev;
}

bool lang_accept(parser *p, lang_tok k)
{
	if (lang_peek(p)->kind != k)
		return false;
	lang_advance(p);
	return true;
}

bool lang_expect(parser *p, lang_tok k, const char *context)
{
	if (lang_accept(p, k))
		return true;
	if (k == LTK_COMMA) /* POV-Ray's Parse_Comma: a comma between items may be left out */
		return true;
	return lang_error_found(p, "expected %s %s", lang_tok_name(k), context);
}

bool lang_expect_close(parser *p, diag_loc open, const char *what)
{
	if (lang_accept(p, LTK_RBRACE))
		return true;
	bool at_eof = lang_peek(p)->kind == LTK_EOF && !p->failed;
	lang_error_found(p, "expected '}' to close '%s' (opened at line %u)", what, open.line);
	if (at_eof)
		note(p, open, "'%s' opened here", what);
	return false;
}

void lang_skip_optional_semi(parser *p)
{
	if (p->have_tok || p->n_files == 0)
		return;
	for (;;) {
		include_frame *f = &p->files[p->n_files - 1];
		lang_lexer save = f->lx;
		lang_token t;
		diag quiet;
		diag_init(&quiet, NULL);
		bool ok = lex(p, &f->lx, &quiet, &t);
		if (ok && t.kind == LTK_EOF && f->macro && p->n_conds == f->cond_base && end_of_file(p, &t))
			continue; /* a macro's body that ends with the block: `#declare B = Ball(1);` */
		if (!ok || t.kind != LTK_SEMI)
			f->lx = save; /* any error is reported again when the token is read for real */
		return;
	}
}

/* ---- entry point ------------------------------------------------------------------------- */

static const double PI = 3.14159265358979323846;
static const double POV_VERSION = 3.7; /* the language circe reads: `version` before any #version */

/* The floats POV-Ray 3.7 declares before the scene is read, as ordinary globals that a scene may
 * #declare again (its front end adds them: frontend/simplefrontend.h, animationprocessing.cpp).
 * circe renders one frame at a time, so the animation's range is that frame: clock_delta is 0, as
 * in POV-Ray outside an animation. `tau` (2 pi) is POV-Ray 3.8's. */
static bool predeclare(parser *p)
{
	double frame = p->opt.animated ? (double)p->opt.frame : 0.0;
	const struct {
		const char *name;
		double v;
	} pre[] = {
		{"tau", 2.0 * PI},
		{"clock_delta", 0.0},
		{"initial_clock", p->opt.clock},
		{"final_clock", p->opt.clock},
		{"frame_number", frame},
		{"initial_frame", frame},
		{"final_frame", frame},
		{"image_width", p->opt.width > 0 ? p->opt.width : LANG_DEFAULT_WIDTH},
		{"image_height", p->opt.height > 0 ? p->opt.height : LANG_DEFAULT_HEIGHT},
	};
	for (size_t i = 0; i < sizeof pre / sizeof pre[0]; i++) {
		lang_token name = {.kind = LTK_IDENT, .loc = diag_noloc(), .text = pre[i].name,
				   .len = (uint32_t)strlen(pre[i].name)};
		value v = {.kind = VAL_FLOAT, .n = 1, .v = {pre[i].v}};
		if (!define(p, &name, false, &v))
			return false;
	}
	return true;
}

/* FNV-1a (64-bit) offset basis and prime (Fowler, Noll, Vo; draft-eastlake-fnv). */
#define LANG_FNV_BASIS 0xcbf29ce484222325ULL
#define LANG_FNV_PRIME 0x100000001b3ULL

/* The hash of every source d registered after `before` (this parse's files), oldest first: d
 * keeps them newest first. False when memory runs out. */
static bool hash_sources(const diag *d, const diag_source *before, uint64_t *hash)
{
	size_t n = 0;
	for (const diag_source *s = d->sources; s && s != before; s = s->next)
		n++;
	const diag_source **list = mem_alloc(n ? n : 1, sizeof *list);
	if (!list)
		return false;
	size_t k = n;
	for (const diag_source *s = d->sources; s && s != before; s = s->next)
		list[--k] = s;
	uint64_t h = LANG_FNV_BASIS;
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j < list[i]->len; j++)
			h = (h ^ (unsigned char)list[i]->text[j]) * LANG_FNV_PRIME;
	mem_free(list);
	*hash = h;
	return true;
}

lang_status lang_parse_file(const char *path, const lang_options *opt, diag *d, scene **out)
{
	*out = NULL;
	parser *p = mem_calloc(1, sizeof *p);
	scene *sc = scene_new();
	if (!p || !sc) {
		mem_free(p);
		scene_free(sc);
		diag_error(d, diag_noloc(), "out of memory");
		return LANG_NO_MEMORY;
	}
	p->d = d;
	p->sc = sc;
	const diag_source *before = d->sources; /* the sources this parse adds come before it */
	if (opt)
		p->opt = *opt;
	if (!p->opt.read)
		p->opt.read = lang_read_file;
	vecbuf_init(&p->globals, sizeof(symbol));
	vecbuf_init(&p->locals, sizeof(symbol));
	vecbuf_init(&p->rand_streams, sizeof(rng));
	lang_datafiles_init(p);
	p->eof.kind = LTK_EOF;
	p->version = POV_VERSION;
	lang_status st = LANG_OK;
	const diag_source *src;
	int err = open_source(p, path, &src);
	if (err) {
		if (err == ENOMEM) {
			diag_error(d, diag_noloc(), "out of memory");
			st = LANG_NO_MEMORY;
		} else {
			diag_file_error(d, path, "cannot open: %s", strerror(err));
			st = LANG_IO_ERROR;
		}
	} else {
		const char *main_path = arena_strdup(&sc->arena, path);
		if (!main_path) {
			diag_error(d, diag_noloc(), "out of memory");
			st = LANG_NO_MEMORY;
			goto done;
		}
		push_file(p, src, main_path, diag_noloc());
		predeclare(p);
		p->eof.loc = (diag_loc){src, 1, 1};
		while (!p->failed && lang_peek(p)->kind != LTK_EOF)
			if (!lang_statement(p))
				break;
		if (!p->failed && !d->errors)
			lang_lights_flatten(p);
		if (!p->failed && !d->errors) {
			sc->global.working_gamma = scene_working_gamma(&sc->global, p->version);
			scene_resolve_pov_sss(sc, d);
		}
		if (p->failed || d->errors)
			st = LANG_SCENE_ERROR;
		else if (scene_validate(sc, d) > 0)
			st = LANG_SCENE_ERROR;
	}
done:
	lang_datafiles_close(p);
	if (p->failed || d->errors) /* a data file's failure to close */
		st = st == LANG_OK ? LANG_SCENE_ERROR : st;
	vecbuf_free(&p->globals);
	vecbuf_free(&p->locals);
	vecbuf_free(&p->rand_streams);
	mem_free(p->memo);
	mem_free(p);
	if (st == LANG_OK && !hash_sources(d, before, &sc->source_hash)) {
		diag_error(d, diag_noloc(), "out of memory");
		st = LANG_NO_MEMORY;
	}
	if (st != LANG_OK)
		scene_free(sc);
	else
		*out = sc;
	return st;
}

/* test_lex: the lexer's tokens, locations, keyword tables and limits. */
#include "base/diag.h"
#include "check.h"
#include "lang/lex.h"

#include <string.h>

static lang_tok kinds[64];
static uint32_t cols[64], lines[64];

static int lex_all(diag *d, const char *text)
{
	const diag_source *src = diag_add_source(d, "t.pov", text, strlen(text));
	lang_lexer lx;
	lang_lexer_init(&lx, src);
	int n = 0;
	lang_token t;
	do {
		if (!lang_lex(&lx, d, &t))
			return -1;
		kinds[n] = t.kind, lines[n] = t.loc.line, cols[n] = t.loc.col;
		n++;
	} while (t.kind != LTK_EOF && n < 64);
	return n;
}

int main(void)
{
	diag d;
	diag_init(&d, NULL);

	/* Every keyword is found by its spelling (the table is sorted for bisection). */
	for (int k = LANG_FIRST_KEYWORD; k < LANG_FIRST_DIRECTIVE; k++) {
		const char *name = lang_tok_name((lang_tok)k); /* "'word'" */
		size_t len = strlen(name) - 2;
		CHECK(lang_keyword(name + 1, len) == (lang_tok)k, "keyword %s not found", name);
	}
	CHECK(lang_keyword("spheres", 7) == LTK_IDENT, "prefix match");
	CHECK(lang_keyword("spher", 5) == LTK_IDENT, "prefix match");
	CHECK(lang_unsupported_word("photons", 7) && !lang_unsupported_word("difference", 10) &&
		      lang_unsupported_word("uv_mapping", 10) && lang_unsupported_word("agate", 5) &&
		      !lang_unsupported_word("sphere", 6),
	      "unsupported word table");
	/* Every POV-Ray 3.7 reserved word lexes as a circe keyword or as unsupported, never as an
	 * identifier; the table is sorted, so each is found by bisection. */
	CHECK(lang_pov_word_count() >= 500, "POV-Ray's table has %zu words", lang_pov_word_count());
	for (size_t i = 0; i < lang_pov_word_count(); i++) {
		const char *w = lang_pov_word(i);
		CHECK(i == 0 || strcmp(lang_pov_word(i - 1), w) < 0, "'%s' out of order", w);
		CHECK(lang_keyword(w, strlen(w)) != LTK_IDENT || lang_unsupported_word(w, strlen(w)),
		      "POV-Ray word '%s' lexes as an identifier", w);
	}

	int n = lex_all(&d, "sphere { <0, 1.5e1,.5>, R }\r\n// c\n/* b\n */ #declare x<=>=!=\"a\\\"b\"");
	static const lang_tok want[] = {LTK_KW_SPHERE, LTK_LBRACE, LTK_LT, LTK_NUMBER, LTK_COMMA, LTK_NUMBER,
					LTK_COMMA, LTK_NUMBER, LTK_GT, LTK_COMMA, LTK_IDENT, LTK_RBRACE,
					LTK_DIR_DECLARE, LTK_KW_X, LTK_LE, LTK_GE, LTK_NE, LTK_STRING, LTK_EOF};
	CHECK(n == (int)(sizeof want / sizeof want[0]), "token count %d", n);
	for (int i = 0; i < n && i < (int)(sizeof want / sizeof want[0]); i++)
		CHECK(kinds[i] == want[i], "token %d: kind %s, expected %s", i, lang_tok_name(kinds[i]),
		      lang_tok_name(want[i]));
	CHECK(lines[12] == 4 && cols[12] == 5, "#declare at %u:%u, expected 4:5", lines[12], cols[12]);
	CHECK(lines[11] == 1 && cols[11] == 27, "'}' at %u:%u, expected 1:27", lines[11], cols[11]);

	/* Errors stop the lexer and are counted. */
	CHECK(lex_all(&d, "a $") == -1 && d.errors == 1, "bad character");
	CHECK(lex_all(&d, "1e400") == -1 && d.errors == 2, "overflow");
	CHECK(lex_all(&d, "#macro") == 2 && kinds[0] == LTK_DIR_MACRO, "#macro is a directive");
	CHECK(lex_all(&d, "#statistics") == 2 && kinds[0] == LTK_UNSUPPORTED_DIRECTIVE, "#statistics lexes as unsupported");
	CHECK(lex_all(&d, "#fopen") == 2 && kinds[0] == LTK_DIR_FOPEN, "#fopen is a directive");
	CHECK(lex_all(&d, "#  \tdeclare") == 2 && kinds[0] == LTK_DIR_DECLARE, "blanks after '#'");
	CHECK(lex_all(&d, "#\r\n // c\n /* b\n */ declare x") == 3 && kinds[0] == LTK_DIR_DECLARE &&
		      lines[0] == 1 && cols[0] == 1 && lines[1] == 4 && cols[1] == 13,
	      "newlines and comments after '#', as POV-Ray reads them");
	CHECK(lex_all(&d, "# /* b") == -1 && d.errors == 3, "unterminated comment after '#'");
	CHECK(lex_all(&d, "photons") == 2 && kinds[0] == LTK_UNSUPPORTED, "photons lexes as unsupported");
	CHECK(lex_all(&d, "merge") == 2 && kinds[0] == LTK_KW_MERGE, "merge is a keyword");
	diag_free(&d);
	return check_done("test_lex");
}

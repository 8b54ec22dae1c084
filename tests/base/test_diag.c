/* test_diag: the diagnostics printer formats a known location, caret and notes exactly. */
#include "base/diag.h"
#include "check.h"

#include <stdlib.h>
#include <string.h>

int main(void)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *out = open_memstream(&buf, &len);
	diag d;
	diag_init(&d, out);
	const char *text = "camera {\n\tlocation <0, 1, -3>\r\n  look_at <0 1, 0>\n}\n";
	const diag_source *src = diag_add_source(&d, "scenes/a.pov", text, strlen(text));
	CHECK(src != NULL, "source registered");
	diag_error(&d, ((diag_loc){src, 3, 14}), "expected ',' after the x component, found '%s'", "1");
	diag_note(&d, ((diag_loc){src, 1, 8}), "the block opened here");
	diag_warning(&d, ((diag_loc){src, 2, 2}), "tab before");
	diag_error(&d, diag_noloc(), "no place");
	diag_file_error(&d, "missing.obj", "cannot open: %s", "No such file or directory");
	diag_file_warning(&d, "cut.jpg", "the JPEG data %s", "ends early");
	fclose(out);
	const char *expect =
		"scenes/a.pov:3:14: error: expected ',' after the x component, found '1'\n"
		"  look_at <0 1, 0>\n"
		"             ^\n"
		"scenes/a.pov:1:8: note: the block opened here\n"
		"camera {\n"
		"       ^\n"
		"scenes/a.pov:2:2: warning: tab before\n"
		"\tlocation <0, 1, -3>\n"
		"\t^\n"
		"circe: error: no place\n"
		"missing.obj: error: cannot open: No such file or directory\n"
		"cut.jpg: warning: the JPEG data ends early\n";
	CHECK(strcmp(buf, expect) == 0, "got:\n%s\nexpected:\n%s", buf, expect);
	CHECK(d.errors == 3 && d.warnings == 2, "counts %d errors %d warnings", d.errors, d.warnings);

	/* The error limit: the 21st and later are counted, not printed. */
	free(buf);
	buf = NULL;
	out = open_memstream(&buf, &len);
	d.out = out;
	d.errors = 0;
	for (int i = 0; i < 25; i++)
		diag_error(&d, ((diag_loc){src, 1, 1}), "e%d", i);
	fclose(out);
	CHECK(strstr(buf, "e19") && !strstr(buf, "e20"), "limit stops printing after 20");
	CHECK(strstr(buf, "too many errors (limit is 20)") != NULL, "limit is announced");
	CHECK(d.errors == 25, "all 25 counted (%d)", d.errors);
	diag_free(&d);
	free(buf);
	return check_done("test_diag");
}

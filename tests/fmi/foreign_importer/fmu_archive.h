/* fmu_archive: what the plain-C FMI importers (fmu_importer.c for 2.0, fmu3_importer.c for 3.0)
 * share: the FMU archive unpacked into a temp directory, and modelDescription.xml read by plain
 * string parsing. Only libc and libzip; no Stride header. */
#ifndef STRIDE_TESTS_FMU_ARCHIVE_H
#define STRIDE_TESTS_FMU_ARCHIVE_H

#include <stddef.h>

/* The program name that prefixes messages; each importer defines it. */
extern const char* const fmu_program_name;

/* Prints "<program>: error: <message>" to stderr; returns 1, so `return fail(...)` fails. */
int fail(const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Creates a fresh directory "$TMPDIR/<prefix>XXXXXX" into dir[size]; 0 on success. */
int make_temp_dir(char* dir, size_t size, const char* prefix);
/* rm -rf dir (nothing when dir is ""). */
void remove_tree(const char* dir);
/* Unpacks every entry of the ZIP archive `fmu` below `dir`, refusing absolute names, "..",
 * backslashes and symbolic links. */
int unzip_fmu(const char* fmu, const char* dir);

/* The whole file as a NUL-terminated malloc'd string, or NULL. */
char* read_file(const char* path);
/* <dir>/modelDescription.xml with its comments blanked out, or NULL with a message. */
char* read_model_description_text(const char* dir);
/* Blanks out <!-- comments -->, so commented-out elements are not seen. */
void blank_comments(char* text);
/* The next start tag <name ...> at or after `from`: its '<', with *end set to its '>'. */
const char* find_tag(const char* from, const char* name, const char** end);
/* The decoded value of attribute `name` of the tag [tag, end) as a malloc'd string, or NULL. */
char* tag_attribute(const char* tag, const char* end, const char* name);
/* 1 if the attribute is "true" or "1". */
int attribute_is_true(const char* tag, const char* end, const char* name);
/* Sets *out when the attribute is there; 0 unless it is there and not a number. */
int attribute_double(const char* tag, const char* end, const char* name, double* out);

#endif

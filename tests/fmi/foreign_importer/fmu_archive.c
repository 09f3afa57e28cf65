/* fmu_archive: what the plain-C FMI importers (2.0 and 3.0) share: unpacking the FMU archive
 * with libzip into a temp directory, removing it again, and reading modelDescription.xml by plain
 * string parsing (start tags and their attributes; enough for the few facts an importer needs).
 * No Stride header: only libc and libzip. */
#define _XOPEN_SOURCE 700

#include "fmu_archive.h"

#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zip.h>

int fail(const char* format, ...) {
  va_list args;
  fflush(stdout);
  fprintf(stderr, "%s: error: ", fmu_program_name);
  va_start(args, format);
  vfprintf(stderr, format, args);
  va_end(args);
  fprintf(stderr, "\n");
  return 1;
}

static int remove_entry(const char* path, const struct stat* st, int flag, struct FTW* ftw) {
  (void)st;
  (void)flag;
  (void)ftw;
  if (remove(path) != 0)
    fprintf(stderr, "%s: cannot remove %s: %s\n", fmu_program_name, path, strerror(errno));
  return 0;
}

void remove_tree(const char* dir) {
  if (dir[0] != '\0') nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

/* mkdir -p for the directories of `path` below `root` (the part after root). */
static int make_parents(char* path, size_t root_length) {
  char* p = path + root_length + 1;
  for (; *p != '\0'; ++p) {
    if (*p != '/') continue;
    *p = '\0';
    if (mkdir(path, 0755) != 0 && errno != EEXIST) {
      int e = errno;
      *p = '/';
      return fail("cannot create directory for %s: %s", path, strerror(e));
    }
    *p = '/';
  }
  return 0;
}

static int unsafe_entry_name(const char* name) {
  const char* p = name;
  if (name[0] == '\0' || name[0] == '/' || strchr(name, '\\') != NULL) return 1;
  while (*p != '\0') {
    const char* end = strchr(p, '/');
    size_t length = end != NULL ? (size_t)(end - p) : strlen(p);
    if (length == 2 && p[0] == '.' && p[1] == '.') return 1;
    if (end == NULL) break;
    p = end + 1;
  }
  return 0;
}

int unzip_fmu(const char* fmu, const char* dir) {
  int error_code = 0;
  zip_t* archive = zip_open(fmu, ZIP_RDONLY, &error_code);
  zip_int64_t count;
  zip_int64_t i;
  int result = 0;
  char buffer[65536];
  if (archive == NULL) {
    zip_error_t error;
    zip_error_init_with_code(&error, error_code);
    result = fail("cannot open %s as a ZIP archive: %s", fmu, zip_error_strerror(&error));
    zip_error_fini(&error);
    return result;
  }
  count = zip_get_num_entries(archive, 0);
  for (i = 0; i < count && result == 0; ++i) {
    const char* name = zip_get_name(archive, (zip_uint64_t)i, ZIP_FL_ENC_RAW);
    zip_uint8_t opsys = 0;
    zip_uint32_t attributes = 0;
    char path[PATH_MAX];
    size_t name_length;
    if (name == NULL) {
      result = fail("cannot read entry %lld of %s", (long long)i, fmu);
      break;
    }
    if (unsafe_entry_name(name)) {
      result = fail("refusing unsafe entry name \"%s\" (absolute, '..' or backslash)", name);
      break;
    }
    if (zip_file_get_external_attributes(archive, (zip_uint64_t)i, 0, &opsys, &attributes) == 0 &&
        opsys == ZIP_OPSYS_UNIX && S_ISLNK((attributes >> 16) & S_IFMT)) {
      result = fail("refusing symbolic link entry \"%s\"", name);
      break;
    }
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, name) >= sizeof path) {
      result = fail("entry name too long: %s", name);
      break;
    }
    if (make_parents(path, strlen(dir)) != 0) {
      result = 1;
      break;
    }
    name_length = strlen(name);
    if (name[name_length - 1] == '/') {
      if (mkdir(path, 0755) != 0 && errno != EEXIST) {
        result = fail("cannot create %s: %s", path, strerror(errno));
      }
      continue;
    }
    {
      zip_file_t* in = zip_fopen_index(archive, (zip_uint64_t)i, 0);
      int out;
      zip_int64_t n;
      if (in == NULL) {
        result = fail("cannot read entry %s: %s", name, zip_strerror(archive));
        break;
      }
      out = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644);
      if (out < 0) {
        result = fail("cannot create %s: %s", path, strerror(errno));
        zip_fclose(in);
        break;
      }
      while ((n = zip_fread(in, buffer, sizeof buffer)) > 0) {
        if (write(out, buffer, (size_t)n) != (ssize_t)n) {
          result = fail("cannot write %s: %s", path, strerror(errno));
          break;
        }
      }
      if (n < 0) result = fail("cannot decompress %s: %s", name, zip_file_strerror(in));
      close(out);
      zip_fclose(in);
    }
  }
  zip_discard(archive);
  return result;
}

int make_temp_dir(char* dir, size_t size, const char* prefix) {
  const char* tmp = getenv("TMPDIR");
  if ((size_t)snprintf(dir, size, "%s/%sXXXXXX", tmp != NULL && tmp[0] != '\0' ? tmp : "/tmp",
                       prefix) >= size) {
    dir[0] = '\0';
    return fail("TMPDIR is too long");
  }
  if (mkdtemp(dir) == NULL) {
    int e = errno;
    fail("mkdtemp(%s): %s", dir, strerror(e));
    dir[0] = '\0';
    return 1;
  }
  return 0;
}

char* read_file(const char* path) {
  FILE* f = fopen(path, "rb");
  char* text = NULL;
  long size;
  if (f == NULL) return NULL;
  if (fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
    text = malloc((size_t)size + 1);
    if (text != NULL) {
      if (fread(text, 1, (size_t)size, f) != (size_t)size) {
        free(text);
        text = NULL;
      } else {
        text[size] = '\0';
      }
    }
  }
  fclose(f);
  return text;
}

char* read_model_description_text(const char* dir) {
  char path[PATH_MAX];
  char* text;
  if ((size_t)snprintf(path, sizeof path, "%s/modelDescription.xml", dir) >= sizeof path) {
    fail("path of modelDescription.xml is too long");
    return NULL;
  }
  text = read_file(path);
  if (text == NULL) {
    fail("cannot read modelDescription.xml at the root of the FMU");
    return NULL;
  }
  blank_comments(text);
  return text;
}

void blank_comments(char* text) {
  char* p = text;
  while ((p = strstr(p, "<!--")) != NULL) {
    char* end = strstr(p + 4, "-->");
    char* stop = end != NULL ? end + 3 : p + strlen(p);
    memset(p, ' ', (size_t)(stop - p));
    p = stop;
  }
}

static int is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/* Finds the next start tag <name ...>; returns its '<' and sets *end to its '>'. */
const char* find_tag(const char* from, const char* name, const char** end) {
  size_t length = strlen(name);
  const char* p = from;
  while ((p = strchr(p, '<')) != NULL) {
    if (strncmp(p + 1, name, length) == 0 &&
        (is_space(p[1 + length]) || p[1 + length] == '>' || p[1 + length] == '/')) {
      const char* q = p + 1 + length;
      char quote = 0;
      for (; *q != '\0'; ++q) {
        if (quote != 0) {
          if (*q == quote) quote = 0;
        } else if (*q == '"' || *q == '\'') {
          quote = *q;
        } else if (*q == '>') {
          break;
        }
      }
      if (*q == '\0') return NULL;
      *end = q;
      return p;
    }
    ++p;
  }
  return NULL;
}

/* Copies the decoded value of attribute `name` of the tag [tag, end) into a malloc'd string. */
char* tag_attribute(const char* tag, const char* end, const char* name) {
  const char* p = tag + 1;
  size_t name_length = strlen(name);
  while (p < end && !is_space(*p)) ++p; /* element name */
  while (p < end) {
    const char* attr;
    size_t attr_length;
    char quote;
    const char* value;
    const char* value_end;
    while (p < end && is_space(*p)) ++p;
    attr = p;
    while (p < end && *p != '=' && !is_space(*p) && *p != '/' && *p != '>') ++p;
    attr_length = (size_t)(p - attr);
    while (p < end && is_space(*p)) ++p;
    if (p >= end || *p != '=') {
      if (attr_length == 0) ++p;
      continue;
    }
    ++p;
    while (p < end && is_space(*p)) ++p;
    if (p >= end || (*p != '"' && *p != '\'')) return NULL;
    quote = *p++;
    value = p;
    while (p < end && *p != quote) ++p;
    if (p >= end) return NULL;
    value_end = p++;
    if (attr_length == name_length && strncmp(attr, name, name_length) == 0) {
      char* out = malloc((size_t)(value_end - value) + 1);
      char* o = out;
      const char* v = value;
      if (out == NULL) return NULL;
      while (v < value_end) {
        static const struct {
          const char* entity;
          char c;
        } entities[] = {
            {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
        size_t k;
        int decoded = 0;
        for (k = 0; k < sizeof entities / sizeof entities[0]; ++k) {
          size_t n = strlen(entities[k].entity);
          if ((size_t)(value_end - v) >= n && strncmp(v, entities[k].entity, n) == 0) {
            *o++ = entities[k].c;
            v += n;
            decoded = 1;
            break;
          }
        }
        if (!decoded) *o++ = *v++;
      }
      *o = '\0';
      return out;
    }
  }
  return NULL;
}

int attribute_is_true(const char* tag, const char* end, const char* name) {
  char* value = tag_attribute(tag, end, name);
  int result = value != NULL && (strcmp(value, "true") == 0 || strcmp(value, "1") == 0);
  free(value);
  return result;
}

int attribute_double(const char* tag, const char* end, const char* name, double* out) {
  char* value = tag_attribute(tag, end, name);
  char* stop = NULL;
  int result = 0;
  if (value == NULL) return 0;
  errno = 0;
  *out = strtod(value, &stop);
  if (stop == value || *stop != '\0' || errno != 0) {
    result = fail("modelDescription.xml: %s=\"%s\" is not a number", name, value);
  }
  free(value);
  return result;
}

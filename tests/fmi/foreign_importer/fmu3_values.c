/* fmu3_values: the typed Get/Set calls of fmu3_importer: a variable set to its start value (all
 * its elements, nValues = its size), and a variable's values read into a byte trace. */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmu3_importer.h"
#include "fmu_archive.h"

static size_t element_size(fmu3_type type) {
  static const size_t sizes[t_type_count] = {sizeof(fmi3Float32),
                                             sizeof(fmi3Float64),
                                             1,
                                             1,
                                             2,
                                             2,
                                             4,
                                             4,
                                             8,
                                             8,
                                             sizeof(fmi3Boolean),
                                             sizeof(fmi3String),
                                             sizeof(fmi3Binary),
                                             8,
                                             sizeof(fmi3Clock)};
  return sizes[type];
}

/* Get or Set of the numeric and Boolean types through one call site. */
static fmi3Status get_numeric(const fmu3_functions* f, fmi3Instance c, const fmu3_variable* v,
                              void* values) {
  const fmi3ValueReference* vr = &v->vr;
  size_t n = v->size;
  switch (v->type) {
    case t_float32:
      return f->fmi3GetFloat32(c, vr, 1, values, n);
    case t_float64:
      return f->fmi3GetFloat64(c, vr, 1, values, n);
    case t_int8:
      return f->fmi3GetInt8(c, vr, 1, values, n);
    case t_uint8:
      return f->fmi3GetUInt8(c, vr, 1, values, n);
    case t_int16:
      return f->fmi3GetInt16(c, vr, 1, values, n);
    case t_uint16:
      return f->fmi3GetUInt16(c, vr, 1, values, n);
    case t_int32:
      return f->fmi3GetInt32(c, vr, 1, values, n);
    case t_uint32:
      return f->fmi3GetUInt32(c, vr, 1, values, n);
    case t_int64:
    case t_enumeration:
      return f->fmi3GetInt64(c, vr, 1, values, n);
    case t_uint64:
      return f->fmi3GetUInt64(c, vr, 1, values, n);
    case t_boolean:
      return f->fmi3GetBoolean(c, vr, 1, values, n);
    case t_string:
      return f->fmi3GetString(c, vr, 1, values, n);
    default:
      return f->fmi3GetClock(c, vr, 1, values);
  }
}

static fmi3Status set_numeric(const fmu3_functions* f, fmi3Instance c, const fmu3_variable* v,
                              const void* values) {
  const fmi3ValueReference* vr = &v->vr;
  size_t n = v->size;
  switch (v->type) {
    case t_float32:
      return f->fmi3SetFloat32(c, vr, 1, values, n);
    case t_float64:
      return f->fmi3SetFloat64(c, vr, 1, values, n);
    case t_int8:
      return f->fmi3SetInt8(c, vr, 1, values, n);
    case t_uint8:
      return f->fmi3SetUInt8(c, vr, 1, values, n);
    case t_int16:
      return f->fmi3SetInt16(c, vr, 1, values, n);
    case t_uint16:
      return f->fmi3SetUInt16(c, vr, 1, values, n);
    case t_int32:
      return f->fmi3SetInt32(c, vr, 1, values, n);
    case t_uint32:
      return f->fmi3SetUInt32(c, vr, 1, values, n);
    case t_int64:
    case t_enumeration:
      return f->fmi3SetInt64(c, vr, 1, values, n);
    case t_uint64:
      return f->fmi3SetUInt64(c, vr, 1, values, n);
    case t_boolean:
      return f->fmi3SetBoolean(c, vr, 1, values, n);
    case t_string:
      return f->fmi3SetString(c, vr, 1, values, n);
    default:
      return f->fmi3SetClock(c, vr, 1, values);
  }
}

/* One start element (text) into values[i] of the variable's type; 0 on success. */
static int parse_element(fmu3_type type, const char* text, void* values, size_t i) {
  char* stop = NULL;
  unsigned char* at = (unsigned char*)values + i * element_size(type);
  errno = 0;
  if (type == t_boolean) {
    fmi3Boolean b = strcmp(text, "true") == 0 || strcmp(text, "1") == 0;
    if (!b && strcmp(text, "false") != 0 && strcmp(text, "0") != 0) return 1;
    memcpy(at, &b, sizeof b);
    return 0;
  }
  if (type == t_float32 || type == t_float64) {
    double d = strtod(text, &stop);
    float f = (float)d;
    if (type == t_float32) {
      memcpy(at, &f, sizeof f);
    } else {
      memcpy(at, &d, sizeof d);
    }
  } else if (type == t_uint8 || type == t_uint16 || type == t_uint32 || type == t_uint64) {
    unsigned long long u = strtoull(text, &stop, 10);
    uint8_t u8 = (uint8_t)u;
    uint16_t u16 = (uint16_t)u;
    uint32_t u32 = (uint32_t)u;
    uint64_t u64 = (uint64_t)u;
    memcpy(at,
           type == t_uint8    ? (void*)&u8
           : type == t_uint16 ? (void*)&u16
           : type == t_uint32 ? (void*)&u32
                              : (void*)&u64,
           element_size(type));
  } else {
    long long s = strtoll(text, &stop, 10);
    int8_t s8 = (int8_t)s;
    int16_t s16 = (int16_t)s;
    int32_t s32 = (int32_t)s;
    int64_t s64 = (int64_t)s;
    memcpy(at,
           type == t_int8    ? (void*)&s8
           : type == t_int16 ? (void*)&s16
           : type == t_int32 ? (void*)&s32
                             : (void*)&s64,
           element_size(type));
  }
  return stop == text || errno != 0;
}

/* The start values of `v`: a malloc'd array of v->size elements, or NULL with a message. */
static void* start_values(const fmu3_variable* v) {
  void* values = calloc(v->size, element_size(v->type));
  size_t i = 0;
  if (values == NULL) {
    fail("out of memory");
    return NULL;
  }
  if (v->type == t_string) {
    if (v->start_text_count != v->size) {
      fail("%s has %zu <Start> values for %zu elements", v->name, v->start_text_count, v->size);
      free(values);
      return NULL;
    }
    memcpy(values, v->start_texts, v->size * sizeof(fmi3String));
    return values;
  }
  if (v->start != NULL) {
    char* copy = strdup(v->start);
    char* save = NULL;
    char* item;
    for (item = copy != NULL ? strtok_r(copy, " \t\r\n", &save) : NULL; item != NULL && i < v->size;
         item = strtok_r(NULL, " \t\r\n", &save)) {
      if (parse_element(v->type, item, values, i++) != 0) break;
    }
    free(copy);
  }
  if (i != v->size) {
    fail("%s: start \"%s\" does not give %zu %s values", v->name, v->start ? v->start : "", v->size,
         fmu3_type_name(v->type));
    free(values);
    return NULL;
  }
  return values;
}

fmi3Status fmu3_set_start(const fmu3_functions* api, fmi3Instance c, const fmu3_variable* v) {
  fmi3Status status;
  void* values;
  if (v->type == t_binary || v->type == t_clock) return fmi3OK; /* Stride has neither */
  values = start_values(v);
  if (values == NULL) return fmi3Fatal;
  status = set_numeric(api, c, v, values);
  free(values);
  return status;
}

int fmu3_bytes_append(fmu3_bytes* bytes, const void* data, size_t size) {
  if (bytes->size + size > bytes->capacity) {
    size_t capacity = bytes->capacity == 0 ? 256 : bytes->capacity;
    unsigned char* grown;
    while (capacity < bytes->size + size) capacity *= 2;
    grown = realloc(bytes->data, capacity);
    if (grown == NULL) return fail("out of memory");
    bytes->data = grown;
    bytes->capacity = capacity;
  }
  if (size > 0) memcpy(bytes->data + bytes->size, data, size);
  bytes->size += size;
  return 0;
}

int fmu3_append_values(const fmu3_functions* api, fmi3Instance c, const char* instance,
                       const fmu3_variable* v, double time, fmu3_bytes* out) {
  size_t i;
  int result = 0;
  fmi3Status status;
  void* values = calloc(v->size, element_size(v->type));
  size_t* sizes = calloc(v->size, sizeof *sizes);
  if (values == NULL || sizes == NULL) {
    free(values);
    free(sizes);
    return fail("out of memory");
  }
  status = v->type == t_binary ? api->fmi3GetBinary(c, &v->vr, 1, sizes, values, v->size)
                               : get_numeric(api, c, v, values);
  if (status != fmi3OK && status != fmi3Warning) {
    result = fail("fmi3Get%s(%s) of %s (valueReference %u, %zu values) returned %s at t=%g",
                  fmu3_type_name(v->type), instance, v->name, v->vr, v->size,
                  fmu3_status_name(status), time);
  }
  for (i = 0; i < v->size && result == 0; ++i) {
    if (v->type == t_string || v->type == t_binary) {
      const char* p = ((const char* const*)values)[i];
      size_t n = v->type == t_string && p != NULL ? strlen(p) + 1 : sizes[i];
      if (p == NULL && n > 0) {
        result = fail("%s: fmi3Get%s gave a NULL element", v->name, fmu3_type_name(v->type));
      } else {
        result = fmu3_bytes_append(out, p, n);
      }
    } else if ((v->type == t_float64 && isnan(((const double*)values)[i])) ||
               (v->type == t_float32 && isnan(((const float*)values)[i]))) {
      result = fail("%s: output %s[%zu] is NaN at t=%g", instance, v->name, i, time);
    }
  }
  if (result == 0 && v->type != t_string && v->type != t_binary) {
    result = fmu3_bytes_append(out, values, v->size * element_size(v->type));
  }
  free(values);
  free(sizes);
  return result;
}

/* fmu3_model: what fmu3_importer reads from an FMI 3.0 modelDescription.xml: the instantiation
 * token, the <CoSimulation> flags, the default experiment and every variable with its type,
 * causality, variability, array size and start value. */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmu3_importer.h"
#include "fmu_archive.h"

static const char* const k_type_names[t_type_count] = {
    "Float32", "Float64", "Int8",    "UInt8",  "Int16",  "UInt16",      "Int32", "UInt32",
    "Int64",   "UInt64",  "Boolean", "String", "Binary", "Enumeration", "Clock"};

const char* fmu3_type_name(fmu3_type type) {
  return (unsigned)type < t_type_count ? k_type_names[type] : "?";
}

/* The element name right after '<' (up to a space, '/' or '>') is a variable type. */
static int variable_type(const char* tag, fmu3_type* type) {
  size_t length = strcspn(tag + 1, " \t\r\n/>");
  int k;
  for (k = 0; k < t_type_count; ++k) {
    if (strlen(k_type_names[k]) == length && strncmp(tag + 1, k_type_names[k], length) == 0) {
      *type = (fmu3_type)k;
      return 1;
    }
  }
  return 0;
}

static int parse_enum(const char* text, const char* const* names, int count, int fallback) {
  int k;
  if (text == NULL) return fallback;
  for (k = 0; k < count; ++k) {
    if (strcmp(text, names[k]) == 0) return k;
  }
  return -1;
}

static int parse_size(const char* text, unsigned long long* out) {
  char* stop = NULL;
  if (text == NULL || text[0] == '\0' || text[0] == '-') return 1;
  errno = 0;
  *out = strtoull(text, &stop, 10);
  return *stop != '\0' || errno != 0;
}

/* The children of a variable element up to its end tag: <Dimension>, <Start>, <Alias>. */
static int read_children(const char* from, const char* close, fmu3_variable* v,
                         const fmu3_model* model) {
  const char* end;
  const char* tag;
  int result = 0;
  v->size = 1;
  for (tag = find_tag(from, "Dimension", &end); tag != NULL && tag < close && result == 0;
       tag = find_tag(end, "Dimension", &end)) {
    char* start = tag_attribute(tag, end, "start");
    char* vr = tag_attribute(tag, end, "valueReference");
    unsigned long long n = 0;
    v->is_array = 1;
    if (start != NULL) {
      if (parse_size(start, &n) != 0 || n == 0) {
        result = fail("%s: <Dimension start=\"%s\"> is not a positive size", v->name, start);
      }
    } else {
      /* a size from a constant or structural UInt64 parameter: its start value */
      unsigned long long ref = 0;
      size_t k;
      int found = 0;
      if (parse_size(vr, &ref) != 0) result = fail("%s: <Dimension> without a size", v->name);
      for (k = 0; k < model->variable_count && result == 0 && !found; ++k) {
        if (model->variables[k].vr == ref && model->variables[k].start != NULL) {
          found = parse_size(model->variables[k].start, &n) == 0;
        }
      }
      if (result == 0 && !found) {
        result = fail("%s: <Dimension valueReference=\"%s\"> names no sized variable before it",
                      v->name, vr != NULL ? vr : "");
      }
    }
    v->size *= (size_t)n;
    free(start);
    free(vr);
  }
  for (tag = find_tag(from, "Start", &end); tag != NULL && tag < close && result == 0;
       tag = find_tag(end, "Start", &end)) {
    char** grown = realloc(v->start_texts, (v->start_text_count + 1) * sizeof *grown);
    if (grown == NULL) return fail("out of memory");
    v->start_texts = grown;
    v->start_texts[v->start_text_count] = tag_attribute(tag, end, "value");
    if (v->start_texts[v->start_text_count++] == NULL) {
      result = fail("%s: <Start> without a value", v->name);
    }
  }
  return result;
}

static int read_variable(const char* tag, const char* end, fmu3_type type, fmu3_model* model,
                         const char** next) {
  static const char* const causalities[] = {"local",  "parameter",   "calculatedParameter", "input",
                                            "output", "independent", "structuralParameter"};
  static const char* const variabilities[] = {"constant", "fixed", "tunable", "discrete",
                                              "continuous"};
  fmu3_variable v;
  char* text;
  unsigned long long vr = 0;
  int causality;
  int variability;
  int result = 0;
  fmu3_variable* grown;
  memset(&v, 0, sizeof v);
  v.type = type;
  v.name = tag_attribute(tag, end, "name");
  v.start = tag_attribute(tag, end, "start");
  text = tag_attribute(tag, end, "valueReference");
  if (v.name == NULL || parse_size(text, &vr) != 0 || vr > 0xFFFFFFFFull) {
    result = fail("a <%s> has no name or no valid valueReference", fmu3_type_name(type));
  }
  v.vr = (fmi3ValueReference)vr;
  free(text);
  text = tag_attribute(tag, end, "causality");
  causality = parse_enum(text, causalities, 7, c_local);
  free(text);
  text = tag_attribute(tag, end, "variability");
  variability = parse_enum(text, variabilities, 5, -2);
  free(text);
  if (variability == -2) { /* the default: fixed for parameters, continuous for floats */
    variability = causality == c_parameter || causality == c_calculated_parameter ||
                          causality == c_structural_parameter
                      ? v_fixed
                  : type == t_float32 || type == t_float64 ? v_continuous
                                                           : v_discrete;
  }
  if (result == 0 && (causality < 0 || variability < 0)) {
    result = fail("%s: unknown causality or variability", v.name);
  }
  v.causality = (fmu3_causality)causality;
  v.variability = (fmu3_variability)variability;
  *next = end;
  v.size = 1;
  if (result == 0 && end[-1] != '/') { /* not self-closing: children up to </Type> */
    char close_tag[32];
    const char* close;
    snprintf(close_tag, sizeof close_tag, "</%s", fmu3_type_name(type));
    close = strstr(end, close_tag);
    if (close == NULL) {
      result = fail("%s: no %s>", v.name, close_tag);
    } else {
      result = read_children(end, close, &v, model);
      *next = close;
    }
  }
  grown = realloc(model->variables, (model->variable_count + 1) * sizeof *grown);
  if (grown == NULL) {
    result = fail("out of memory");
  } else {
    model->variables = grown;
    model->variables[model->variable_count++] = v; /* freed with the model, also on error */
  }
  return result;
}

static int read_variables(const char* text, fmu3_model* model) {
  const char* end;
  const char* list = find_tag(text, "ModelVariables", &end);
  const char* stop;
  const char* p;
  if (list == NULL) return 0;
  stop = strstr(end, "</ModelVariables");
  if (stop == NULL) return fail("modelDescription.xml: <ModelVariables> is not closed");
  for (p = strchr(end, '<'); p != NULL && p < stop; p = strchr(p + 1, '<')) {
    fmu3_type type;
    const char* tag_end = strchr(p, '>');
    if (tag_end == NULL) return fail("modelDescription.xml: a tag is not closed");
    if (!variable_type(p, &type)) continue;
    if (read_variable(p, tag_end, type, model, &p) != 0) return 1;
  }
  return 0;
}

int fmu3_read_model(const char* dir, fmu3_model* model) {
  const char* tag;
  const char* end;
  char* version;
  int result = 0;
  char* text = read_model_description_text(dir);
  memset(model, 0, sizeof *model);
  model->step_size = 0.01;
  if (text == NULL) return 1;
  tag = find_tag(text, "fmiModelDescription", &end);
  if (tag == NULL) {
    free(text);
    return fail("modelDescription.xml has no <fmiModelDescription>");
  }
  version = tag_attribute(tag, end, "fmiVersion");
  if (version == NULL || strncmp(version, "3.", 2) != 0) {
    result = fail("fmiVersion is \"%s\", expected 3.x", version != NULL ? version : "");
  }
  free(version);
  model->token = tag_attribute(tag, end, "instantiationToken");
  if (result == 0 && model->token == NULL) result = fail("modelDescription.xml has no token");
  model->has_model_exchange = find_tag(text, "ModelExchange", &end) != NULL;
  tag = find_tag(text, "CoSimulation", &end);
  if (result == 0 && tag == NULL) result = fail("modelDescription.xml has no <CoSimulation>");
  if (result == 0) {
    model->model_identifier = tag_attribute(tag, end, "modelIdentifier");
    if (model->model_identifier == NULL || model->model_identifier[0] == '\0' ||
        strchr(model->model_identifier, '/') != NULL) {
      result = fail("<CoSimulation> has no usable modelIdentifier");
    }
    model->only_once_per_process =
        attribute_is_true(tag, end, "canBeInstantiatedOnlyOncePerProcess");
    model->can_get_and_set_fmu_state = attribute_is_true(tag, end, "canGetAndSetFMUState");
    model->can_serialize_fmu_state = attribute_is_true(tag, end, "canSerializeFMUState");
    model->provides_directional_derivatives =
        attribute_is_true(tag, end, "providesDirectionalDerivatives");
    model->provides_adjoint_derivatives = attribute_is_true(tag, end, "providesAdjointDerivatives");
    model->has_event_mode = attribute_is_true(tag, end, "hasEventMode");
    model->provides_per_element_dependencies =
        attribute_is_true(tag, end, "providesPerElementDependencies");
    {
      double order = 0.0;
      result = result || attribute_double(tag, end, "maxOutputDerivativeOrder", &order);
      model->max_output_derivative_order = (int)order;
    }
  }
  tag = find_tag(text, "DefaultExperiment", &end);
  if (result == 0 && tag != NULL) {
    result = attribute_double(tag, end, "stepSize", &model->step_size) ||
             attribute_double(tag, end, "startTime", &model->start_time);
    if (result == 0 && !(model->step_size > 0.0)) {
      result = fail("DefaultExperiment stepSize %g is not positive", model->step_size);
    }
  }
  if (result == 0) result = read_variables(text, model);
  free(text);
  return result;
}

void fmu3_free_model(fmu3_model* model) {
  size_t i;
  size_t k;
  for (i = 0; i < model->variable_count; ++i) {
    fmu3_variable* v = &model->variables[i];
    free(v->name);
    free(v->start);
    for (k = 0; k < v->start_text_count; ++k) free(v->start_texts[k]);
    free(v->start_texts);
  }
  free(model->variables);
  free(model->token);
  free(model->model_identifier);
  memset(model, 0, sizeof *model);
}

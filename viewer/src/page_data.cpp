#include "page_data.hpp"

#include "json_writer.hpp"

namespace stride::viewer {

namespace {

void write_numbers(json_writer& w, const auto& values) {
  w.begin_array();
  for (const auto v : values) w.value(static_cast<double>(v));
  w.end_array();
}

void write_pose(json_writer& w, const robot::pose& p) {
  w.begin_object();
  w.key("R");
  write_numbers(w, p.rotation);
  w.key("p");
  write_numbers(w, p.position);
  w.end_object();
}

const char* shape_name(robot::shape_type t) {
  switch (t) {
    case robot::shape_type::box:
      return "box";
    case robot::shape_type::cylinder:
      return "cylinder";
    case robot::shape_type::sphere:
      return "sphere";
    case robot::shape_type::capsule:
      return "capsule";
    case robot::shape_type::mesh:
      return "mesh";
  }
  return "box";
}

const char* joint_name(robot::joint_type t) {
  return t == robot::joint_type::prismatic ? "prismatic" : "revolute";
}

void write_model(json_writer& w, const robot::robot_model& model) {
  w.begin_object();
  w.key("name").value(model.name);
  w.key("fixed_base").value(model.fixed_base);
  w.key("bodies").begin_array();
  for (const auto& b : model.bodies) {
    w.begin_object();
    w.key("link").value(b.link);
    w.key("shapes").begin_array();
    for (const auto& s : b.shapes) {
      w.begin_object();
      w.key("type").value(shape_name(s.type));
      w.key("size");
      write_numbers(w, s.size);
      w.key("origin");
      write_pose(w, s.origin);
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.key("joints").begin_array();
  for (const auto& j : model.joints) {
    w.begin_object();
    w.key("name").value(j.name);
    w.key("type").value(joint_name(j.type));
    w.key("parent").value(j.parent_body);
    w.key("child").value(j.child_body);
    w.key("origin");
    write_pose(w, j.origin);
    w.key("axis");
    write_numbers(w, j.axis);
    w.key("servo").value(j.servo_id);
    w.end_object();
  }
  w.end_array();
  w.key("links").begin_array();
  for (const auto& l : model.links) {
    w.begin_object();
    w.key("name").value(l.name);
    w.key("body").value(l.body);
    w.key("in_body");
    write_pose(w, l.in_body);
    w.end_object();
  }
  w.end_array();
  w.end_object();
}

void write_frames(json_writer& w, const recorded_frames& f) {
  w.begin_object();
  const std::pair<const char*, const std::vector<double>*> columns[] = {
      {"t", &f.t},       {"x", &f.x},         {"y", &f.y},    {"z", &f.z},
      {"roll", &f.roll}, {"pitch", &f.pitch}, {"yaw", &f.yaw}};
  for (const auto& [name, values] : columns) {
    w.key(name);
    write_numbers(w, *values);
  }
  // by servo ID − 1; IDs that carry no joint are null
  w.key("q").begin_array();
  for (const auto& q : f.q) {
    if (q.empty()) {
      w.begin_array().end_array();
    } else {
      write_numbers(w, q);
    }
  }
  w.end_array();
  if (!f.fallen.empty()) {
    w.key("fallen");
    write_numbers(w, f.fallen);
  }
  w.end_object();
}

}  // namespace

std::string model_json(const robot::robot_model& model) {
  json_writer w;
  write_model(w, model);
  return w.str();
}

std::string page_json(const robot::robot_model& model, const recorded_frames& frames,
                      const page_content& content) {
  json_writer w;
  w.begin_object();
  w.key("title").value(content.title);
  w.key("model");
  write_model(w, model);
  w.key("frames");
  write_frames(w, frames);
  w.key("falls");
  write_numbers(w, frames.falls);
  w.key("parameters").begin_array();
  for (const auto& p : content.parameters) w.value(p);
  w.end_array();
  w.key("state").begin_array();
  for (const auto& [name, values] : frames.state) {
    w.begin_object();
    w.key("name").value(name);
    w.key("values");
    write_numbers(w, values);
    w.end_object();
  }
  w.end_array();
  w.key("episodes").begin_array();
  for (const auto& e : content.episodes) {
    w.begin_object();
    w.key("label").value(e.label);
    w.key("from").value(e.from);
    w.key("to").value(e.to);
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return w.str();
}

}  // namespace stride::viewer

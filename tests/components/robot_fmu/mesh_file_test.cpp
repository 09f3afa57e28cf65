// Mesh files (mesh_file.cpp): ASCII and binary STL, Collada with a unit, scale, mirroring, errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "stride/robot/mesh_file.hpp"

namespace {

using stride::robot::load_mesh;
using stride::robot::model_error;
using stride::robot::triangle_mesh;
using stride::robot::vec3;
using testing::HasSubstr;

const std::string k_data = STRIDE_TEST_DATA_DIR;

std::string error_of(const std::string& path, const vec3& scale = {1, 1, 1}) {
  try {
    (void)load_mesh(path, scale);
  } catch (const model_error& e) {
    return e.what();
  }
  return "<no model_error>";
}

// smallest and largest coordinate along each axis
std::array<double, 6> bounds(const triangle_mesh& m) {
  std::array<double, 6> b = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (std::size_t k = 0; k < m.vertices.size(); ++k) {
    const std::size_t a = k % 3;
    b[2 * a] = std::min(b[2 * a], m.vertices[k]);
    b[2 * a + 1] = std::max(b[2 * a + 1], m.vertices[k]);
  }
  return b;
}

// divergence theorem: sum of v0 · (v1 × v2) / 6 over the triangles is the enclosed volume,
// positive only when every triangle winds counter-clockwise seen from outside
double signed_volume(const triangle_mesh& m) {
  double v = 0.0;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const double* a = &m.vertices[3 * m.indices[t]];
    const double* b = &m.vertices[3 * m.indices[t + 1]];
    const double* c = &m.vertices[3 * m.indices[t + 2]];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v / 6.0;
}

// the unit cube [-0.5, 0.5]^3 as a binary STL: 80-byte header, u32 count, per triangle a normal,
// three vertices (f32 each) and a u16 attribute (the layout of the STL format)
std::string write_binary_cube() {
  const std::string path =
      (std::filesystem::temp_directory_path() / "stride_mesh_file_test_cube.stl").string();
  std::ofstream out(path, std::ios::binary);
  const char header[80] = "binary unit cube";
  out.write(header, 80);
  const std::uint32_t n = 12;
  out.write(reinterpret_cast<const char*>(&n), 4);
  // two triangles per face: corners a, b, c and a, c, d of the face's counter-clockwise quad
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {-1, 1}) {
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;  // (u, v, axis) right-handed: (u × v) = +axis
      auto corner = [&](float a, float b) {
        std::array<float, 3> p{};
        p[static_cast<std::size_t>(axis)] = 0.5F * static_cast<float>(sign);
        p[static_cast<std::size_t>(u)] = a;
        p[static_cast<std::size_t>(v)] = sign > 0 ? b : -b;  // mirrored for the -axis face
        return p;
      };
      const std::array<std::array<float, 3>, 4> q = {corner(-0.5F, -0.5F), corner(0.5F, -0.5F),
                                                     corner(0.5F, 0.5F), corner(-0.5F, 0.5F)};
      for (const auto& tri : {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
        std::array<float, 3> normal{};
        normal[static_cast<std::size_t>(axis)] = static_cast<float>(sign);
        out.write(reinterpret_cast<const char*>(normal.data()), 12);
        for (const auto& p : tri) out.write(reinterpret_cast<const char*>(p.data()), 12);
        const std::uint16_t attribute = 0;
        out.write(reinterpret_cast<const char*>(&attribute), 2);
      }
    }
  }
  return path;
}

TEST(mesh_file, an_ascii_stl_is_read_scaled_and_closed) {
  const auto m = load_mesh(k_data + "/unit_cube.stl", {0.2, 0.1, 0.05});
  EXPECT_EQ(m->indices.size(), 36u);  // 12 triangles as written in the file
  EXPECT_EQ(m->file, k_data + "/unit_cube.stl");
  const auto b = bounds(*m);
  EXPECT_DOUBLE_EQ(b[0], -0.1);
  EXPECT_DOUBLE_EQ(b[1], 0.1);
  EXPECT_DOUBLE_EQ(b[2], -0.05);
  EXPECT_DOUBLE_EQ(b[3], 0.05);
  EXPECT_DOUBLE_EQ(b[4], -0.025);
  EXPECT_DOUBLE_EQ(b[5], 0.025);
  EXPECT_NEAR(signed_volume(*m), 0.2 * 0.1 * 0.05, 1e-15);  // outward, closed
}

TEST(mesh_file, a_binary_stl_gives_the_same_box) {
  const std::string path = write_binary_cube();
  const auto m = load_mesh(path, {2.0, 3.0, 4.0});
  std::filesystem::remove(path);
  EXPECT_EQ(m->indices.size(), 36u);
  const auto b = bounds(*m);
  EXPECT_DOUBLE_EQ(b[0], -1.0);
  EXPECT_DOUBLE_EQ(b[3], 1.5);
  EXPECT_DOUBLE_EQ(b[5], 2.0);
  EXPECT_NEAR(signed_volume(*m), 24.0, 1e-12);
}

TEST(mesh_file, a_mirroring_scale_keeps_the_triangles_facing_out) {
  const auto m = load_mesh(k_data + "/unit_cube.stl", {-1.0, 1.0, 1.0});
  EXPECT_NEAR(signed_volume(*m), 1.0, 1e-15);
}

TEST(mesh_file, collada_applies_its_unit_but_not_its_up_axis) {
  // box_1x2x3_dm.dae: a 1 x 2 x 3 box in decimetres (<unit meter="0.1">), <up_axis>Z_UP</up_axis>:
  // 0.1 x 0.2 x 0.3 m with the 0.3 m side still along z
  const auto m = load_mesh(k_data + "/box_1x2x3_dm.dae", {1.0, 1.0, 2.0});
  EXPECT_EQ(m->indices.size(), 36u);
  const auto b = bounds(*m);
  EXPECT_NEAR(b[1] - b[0], 0.1, 1e-7);  // float vertices in assimp
  EXPECT_NEAR(b[3] - b[2], 0.2, 1e-7);
  EXPECT_NEAR(b[5] - b[4], 0.6, 1e-7);
  EXPECT_NEAR(signed_volume(*m), 0.1 * 0.2 * 0.6, 1e-8);
}

TEST(mesh_file, unreadable_and_unsupported_files_are_named) {
  EXPECT_THAT(error_of(k_data + "/no_such_mesh.stl"),
              HasSubstr("mesh file '" + k_data + "/no_such_mesh.stl' cannot be read"));
  EXPECT_THAT(error_of(k_data + "/pendulum.urdf"),
              HasSubstr("unsupported format '.urdf' (supported: STL (binary or ASCII) and "
                        "Collada (.dae))"));
  // a file with the right name that is not a mesh: assimp's own reason plus the formats
  const std::string garbage =
      (std::filesystem::temp_directory_path() / "stride_mesh_file_test_garbage.stl").string();
  std::ofstream(garbage) << "this is not a mesh\n";
  const std::string msg = error_of(garbage);
  std::filesystem::remove(garbage);
  EXPECT_THAT(msg, HasSubstr("mesh file '" + garbage + "'"));
  EXPECT_THAT(msg, HasSubstr("supported: STL"));
  EXPECT_THAT(error_of(k_data + "/unit_cube.stl", {1.0, 0.0, 1.0}),
              HasSubstr("scale must be finite and non-zero"));
}

}  // namespace

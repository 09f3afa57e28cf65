// Mesh files through assimp: every format it reads becomes one flat list of triangles; only the
// formats named below are accepted, so a model does not silently depend on an importer that
// another assimp build may lack.
#include "stride/robot/mesh_file.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

namespace stride::robot {

namespace {

constexpr const char* k_formats = "STL (binary or ASCII) and Collada (.dae)";

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::shared_ptr<const triangle_mesh> load_mesh(const std::string& path, const vec3& scale) {
  const std::string ext = lower_extension(path);
  if (ext != ".stl" && ext != ".dae") {
    throw model_error("mesh file '" + path + "': unsupported format '" + ext +
                      "' (supported: " + k_formats + ")");
  }
  for (double s : scale) {
    if (!std::isfinite(s) || s == 0.0) {
      throw model_error("mesh file '" + path + "': scale must be finite and non-zero");
    }
  }
  Assimp::Importer importer;
  // URDF link frames take the vertices as written; assimp would otherwise turn a Z-up file Y-up
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (scene == nullptr) {
    throw model_error("mesh file '" + path + "' cannot be read: " + importer.GetErrorString() +
                      " (supported: " + k_formats + ")");
  }
  auto mesh = std::make_shared<triangle_mesh>();
  mesh->file = path;
  // a mirroring scale turns the triangles inside out: their winding is reversed to compensate
  const bool mirrored = scale[0] * scale[1] * scale[2] < 0.0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& am = *scene->mMeshes[m];
    if ((am.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    const std::size_t first = mesh->vertices.size() / 3;
    if (first + am.mNumVertices > std::numeric_limits<std::uint32_t>::max()) {
      throw model_error("mesh file '" + path + "': too many vertices");
    }
    for (unsigned v = 0; v < am.mNumVertices; ++v) {
      const aiVector3D& p = am.mVertices[v];
      mesh->vertices.push_back(scale[0] * static_cast<double>(p.x));
      mesh->vertices.push_back(scale[1] * static_cast<double>(p.y));
      mesh->vertices.push_back(scale[2] * static_cast<double>(p.z));
    }
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
      const aiFace& face = am.mFaces[f];
      if (face.mNumIndices != 3) continue;
      const auto base = static_cast<std::uint32_t>(first);
      mesh->indices.push_back(base + face.mIndices[0]);
      mesh->indices.push_back(base + face.mIndices[mirrored ? 2 : 1]);
      mesh->indices.push_back(base + face.mIndices[mirrored ? 1 : 2]);
    }
  }
  if (mesh->indices.empty()) throw model_error("mesh file '" + path + "' has no triangles");
  for (double x : mesh->vertices) {
    if (!std::isfinite(x)) throw model_error("mesh file '" + path + "': a vertex is not finite");
  }
  return mesh;
}

}  // namespace stride::robot

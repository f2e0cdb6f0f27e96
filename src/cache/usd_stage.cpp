#include "cache/usd_stage.hpp"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <map>
#include <set>

#include "core/error.hpp"
#include "core/look.hpp"
#include "core/output_file.hpp"
#include "core/version.hpp"
#include "model/model.hpp"

namespace dinam {

struct UsdStageWriter::Prim {
  enum class Kind { kMesh, kCurves };
  Kind kind = Kind::kMesh;
  std::string name;
  Index object = 0;
  Index first_node = 0;  // the object's
  Vec3f color = Vec3f::Ones();
  std::vector<Index> nodes;    // (n_points) the model's node at each point
  std::vector<Index> counts;   // faceVertexCounts or curveVertexCounts
  std::vector<Index> indices;  // faceVertexIndices, into the points (meshes only)
  // primvars:st, face-varying: each distinct pair of texture coordinates once, in the order the
  // face corners meet them, and each corner's (faceVertexIndices' order) index into them, so a
  // seam keeps a pair on each side. Empty when the object has none.
  std::vector<Eigen::Vector2f> uvs;
  std::vector<Index> uv_indices;
  std::string display_name;  // the object's own name where the prim's is not it; else empty
  std::string texture;       // the cache's copy of its texture, beside the stage; or empty
  std::filesystem::path samples_path;
  std::FILE* samples = nullptr;
  std::vector<std::array<Vec3f, 2>> extents;  // (frames) the box of the points at each frame

  ~Prim() {
    if (samples != nullptr) {
      std::fclose(samples);
    }
  }
};

namespace {

using Prim = UsdStageWriter::Prim;

// The scope under /dinam that holds a Material per prim, named as the prim.
constexpr const char* kLooksScope = "Looks";

// The bars of one object that a BasisCurves prim draws, chained into polylines: a curve runs on
// through every node that joins exactly two of the bars and stops at any other node, so a rope
// is one curve and a lattice a curve per bar. `bars` are of one object. Returns the curves as
// node ids.
std::vector<std::vector<Index>> chain_bars(const Model& model, const std::vector<Index>& bars) {
  std::vector<std::vector<Index>> curves;
  if (bars.empty()) {
    return curves;
  }
  const ModelObject& object = model.objects[model.node_object[model.bar_nodes[2 * bars[0]]]];
  const Index first = object.first_node;
  const Index count = object.node_count;
  // The bars at each node of the object: incident[offsets[v] .. offsets[v + 1]).
  std::vector<Index> offsets(static_cast<std::size_t>(count) + 1, 0);
  for (const Index b : bars) {
    ++offsets[model.bar_nodes[2 * b] - first + 1];
    ++offsets[model.bar_nodes[2 * b + 1] - first + 1];
  }
  for (Index v = 0; v < count; ++v) {
    offsets[v + 1] += offsets[v];
  }
  std::vector<Index> incident(static_cast<std::size_t>(offsets[count]));
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t k = 0; k < bars.size(); ++k) {
    for (int end = 0; end < 2; ++end) {
      const Index v = model.bar_nodes[2 * bars[k] + end] - first;
      incident[fill[v]++] = static_cast<Index>(k);
    }
  }
  auto degree = [&](Index v) { return offsets[v + 1] - offsets[v]; };
  std::vector<bool> used(bars.size(), false);
  auto unused_bar_at = [&](Index v) -> Index {
    for (Index k = offsets[v]; k < offsets[v + 1]; ++k) {
      if (!used[incident[k]]) {
        return incident[k];
      }
    }
    return -1;
  };
  auto other_end = [&](Index k, Index v) {
    const Index a = model.bar_nodes[2 * bars[k]] - first;
    return a == v ? model.bar_nodes[2 * bars[k] + 1] - first : a;
  };
  // Walks from node v along unused bars, through nodes of degree 2.
  auto walk = [&](Index v, Index k) {
    std::vector<Index>& curve = curves.emplace_back(1, v + first);
    while (k >= 0) {
      used[k] = true;
      v = other_end(k, v);
      curve.push_back(v + first);
      k = degree(v) == 2 ? unused_bar_at(v) : -1;
    }
  };
  for (Index v = 0; v < count; ++v) {
    if (degree(v) != 2) {
      for (Index k = unused_bar_at(v); k >= 0; k = unused_bar_at(v)) {
        walk(v, k);
      }
    }
  }
  // What is left are closed loops of degree-2 nodes: each a curve that ends where it began.
  for (std::size_t k = 0; k < bars.size(); ++k) {
    if (!used[k]) {
      walk(model.bar_nodes[2 * bars[k]] - first, static_cast<Index>(k));
    }
  }
  return curves;
}

std::string unique_name(std::string name, std::set<std::string>& taken) {
  if (taken.insert(name).second) {
    return name;
  }
  for (int k = 2;; ++k) {
    std::string candidate = fmt::format("{}_{}", name, k);
    if (taken.insert(candidate).second) {
      return candidate;
    }
  }
}

// The object's texture coordinates at each corner of its faces, in the order `mesh` lists the
// corners, as USD's face-varying primvar: its distinct pairs and an index per corner.
void add_face_varying_uvs(const Model& model, Index object, Prim& mesh) {
  std::map<std::pair<float, float>, Index> index_of;
  for (Index f = 0; f < model.face_count(); ++f) {
    if (model.node_object[model.face_nodes[model.face_offsets[f]]] != object) {
      continue;
    }
    for (Index k = model.face_offsets[f]; k < model.face_offsets[f + 1]; ++k) {
      // USD's v runs up the picture, the model's down.
      const std::pair<float, float> uv{model.face_uv[k].x(), 1.0f - model.face_uv[k].y()};
      const auto [it, added] = index_of.emplace(uv, static_cast<Index>(mesh.uvs.size()));
      if (added) {
        mesh.uvs.emplace_back(uv.first, uv.second);
      }
      mesh.uv_indices.push_back(it->second);
    }
  }
}

std::vector<std::unique_ptr<Prim>> make_prims(const Model& model,
                                              const std::vector<ObjectLook>& looks) {
  std::vector<std::unique_ptr<Prim>> prims;
  std::set<std::string> taken{kLooksScope};
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ModelObject& object = model.objects[o];
    const auto id = static_cast<Index>(o);
    auto mesh = std::make_unique<Prim>();
    mesh->object = id;
    mesh->first_node = object.first_node;
    mesh->color = object.color;
    if (looks[o].surface) {
      for (Index f = 0; f < model.face_count(); ++f) {
        const Index begin = model.face_offsets[f];
        if (model.node_object[model.face_nodes[begin]] != id) {
          continue;
        }
        mesh->counts.push_back(model.face_offsets[f + 1] - begin);
        for (Index k = begin; k < model.face_offsets[f + 1]; ++k) {
          mesh->indices.push_back(model.face_nodes[k] - object.first_node);
        }
      }
    }
    // The bars a BasisCurves prim draws: all of a wire object's, a surface's loose ones.
    std::vector<Index> wires;
    for (Index b = object.first_bar; b < object.first_bar + object.bar_count; ++b) {
      if (looks[o].wires || mesh->counts.empty() || model.bar_on_face[b] == 0) {
        wires.push_back(b);
      }
    }
    const std::string name = usd_prim_name(object.name);
    if (!mesh->counts.empty()) {
      mesh->name = unique_name(name, taken);
      for (Index i = object.first_node; i < object.first_node + object.node_count; ++i) {
        mesh->nodes.push_back(i);
      }
      if (object.has_uvs && !model.face_uv.empty()) {
        add_face_varying_uvs(model, id, *mesh);
      }
      mesh->display_name = mesh->name == object.name ? "" : object.name;
      prims.push_back(std::move(mesh));
    }
    if (!wires.empty()) {
      auto curves = std::make_unique<Prim>();
      curves->kind = Prim::Kind::kCurves;
      curves->object = id;
      curves->first_node = object.first_node;
      curves->color = object.color;
      const bool alone = prims.empty() || prims.back()->object != id;
      curves->name = unique_name(alone ? name : name + "_wires", taken);
      const std::string shown = alone ? object.name : object.name + " wires";
      curves->display_name = curves->name == shown ? "" : shown;
      for (const std::vector<Index>& curve : chain_bars(model, wires)) {
        curves->counts.push_back(static_cast<Index>(curve.size()));
        curves->nodes.insert(curves->nodes.end(), curve.begin(), curve.end());
      }
      prims.push_back(std::move(curves));
    }
  }
  return prims;
}

// fmt writes the shortest decimal that reads back as the same float, in a form USD reads.
void append_point(fmt::memory_buffer& text, const Vec3f& p) {
  fmt::format_to(std::back_inserter(text), "({}, {}, {})", p.x(), p.y(), p.z());
}

template <typename T, typename Format>
void append_array(fmt::memory_buffer& text, const std::vector<T>& values, Format format) {
  text.push_back('[');
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k > 0) {
      fmt::format_to(std::back_inserter(text), ", ");
    }
    format(values[k]);
  }
  text.push_back(']');
}

[[noreturn]] void throw_write_error(const std::filesystem::path& path) {
  throw WriteError(
      fmt::format("cannot write the USD stage part {}: {}", path.string(), std::strerror(errno)));
}

void write_text(std::FILE* out, const fmt::memory_buffer& text, const std::filesystem::path& path) {
  if (std::fwrite(text.data(), 1, text.size(), out) != text.size()) {
    throw_write_error(path);
  }
}

// A string as USD's text form quotes it.
std::string usd_string(const std::string& value) {
  std::string quoted;
  for (const char c : value) {
    if (c == '"' || c == '\\') {
      quoted.push_back('\\');
    }
    quoted.push_back(c == '\n' ? ' ' : c);
  }
  return quoted;
}

// The prim's Material: a UsdPreviewSurface of the object's colour, or of its texture's where it
// wears one (read through the mesh's st), with its finish's roughness and metalness; what
// Houdini, Maya, usdview and Omniverse show without dinam's renderer.
void append_material(fmt::memory_buffer& text, const Prim& prim, const Finish& finish) {
  auto put = [&]<typename... Args>(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(text), format, std::forward<Args>(args)...);
  };
  const std::string path = fmt::format("/dinam/{}/{}", kLooksScope, prim.name);
  put("        def Material \"{}\"\n        {{\n"
      "            token outputs:surface.connect = <{}/surface.outputs:surface>\n\n"
      "            def Shader \"surface\"\n            {{\n"
      "                uniform token info:id = \"UsdPreviewSurface\"\n",
      prim.name, path);
  if (prim.texture.empty()) {
    put("                color3f inputs:diffuseColor = ({}, {}, {})\n", prim.color.x(),
        prim.color.y(), prim.color.z());
  } else {
    put("                color3f inputs:diffuseColor.connect = <{}/texture.outputs:rgb>\n", path);
  }
  put("                float inputs:roughness = {}\n                float inputs:metallic = {}\n"
      "                token outputs:surface\n            }}\n",
      finish.roughness, finish.metallic);
  if (!prim.texture.empty()) {
    put("\n            def Shader \"texture\"\n            {{\n"
        "                uniform token info:id = \"UsdUVTexture\"\n"
        "                asset inputs:file = @{}@\n"
        "                token inputs:sourceColorSpace = \"sRGB\"\n"
        "                token inputs:wrapS = \"repeat\"\n"
        "                token inputs:wrapT = \"repeat\"\n"
        "                float2 inputs:st.connect = <{}/st.outputs:result>\n"
        "                float3 outputs:rgb\n            }}\n\n"
        "            def Shader \"st\"\n            {{\n"
        "                uniform token info:id = \"UsdPrimvarReader_float2\"\n"
        "                string inputs:varname = \"st\"\n"
        "                float2 outputs:result\n            }}\n",
        prim.texture, path);
  }
  put("        }}\n");
}

}  // namespace

std::string usd_prim_name(const std::string& object_name) {
  std::string name;
  for (const char c : object_name) {
    const bool keep =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    name.push_back(keep ? c : '_');
  }
  if (name.empty() || (name.front() >= '0' && name.front() <= '9')) {
    name = "_" + name;
  }
  return name;
}

UsdStageWriter::UsdStageWriter(std::filesystem::path folder, std::string file_name,
                               const Model& model, const std::vector<ObjectLook>& looks, double fps,
                               int frame_count)
    : folder_(std::move(folder)),
      file_name_(std::move(file_name)),
      fps_(fps),
      frame_count_(frame_count),
      prims_(make_prims(model, looks)) {
  for (std::size_t p = 0; p < prims_.size(); ++p) {
    Prim& prim = *prims_[p];
    const std::filesystem::path& texture = looks[static_cast<std::size_t>(prim.object)].texture;
    if (prim.kind == Prim::Kind::kMesh) {
      prim.texture = texture.string();  // the cache's copy, beside the stage
    }
    prim.samples_path = folder_ / fmt::format(".{}.{}.samples", file_name_, p);
    prim.samples = std::fopen(prim.samples_path.c_str(), "wbx");
    if (prim.samples == nullptr) {
      throw_write_error(prim.samples_path);
    }
    prim.extents.reserve(static_cast<std::size_t>(frame_count));
  }
}

UsdStageWriter::~UsdStageWriter() = default;

void UsdStageWriter::add_frame(const std::vector<Vec3f>& positions) {
  DINAM_CHECK(frames_written_ < frame_count_);
  ++frames_written_;
  fmt::memory_buffer text;
  for (const std::unique_ptr<Prim>& prim : prims_) {
    text.clear();
    fmt::format_to(std::back_inserter(text), "            {}: [", frames_written_);
    std::array<Vec3f, 2> box{positions[prim->nodes.front()], positions[prim->nodes.front()]};
    for (std::size_t k = 0; k < prim->nodes.size(); ++k) {
      const Vec3f& p = positions[prim->nodes[k]];
      box[0] = box[0].cwiseMin(p);
      box[1] = box[1].cwiseMax(p);
      if (k > 0) {
        fmt::format_to(std::back_inserter(text), ", ");
      }
      append_point(text, p);
    }
    fmt::format_to(std::back_inserter(text), "],\n");
    write_text(prim->samples, text, prim->samples_path);
    prim->extents.push_back(box);
  }
}

void UsdStageWriter::write(const std::vector<ObjectLook>& looks) {
  DINAM_CHECK(frames_written_ == frame_count_);
  OutputFile file(folder_ / file_name_);
  std::FILE* out = file.stream();
  fmt::memory_buffer text;
  auto put = [&]<typename... Args>(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(text), format, std::forward<Args>(args)...);
  };
  put("#usda 1.0\n(\n    doc = \"written by dinam {}: the motion of a simulation, one prim per "
      "object, its points at every frame\"\n    defaultPrim = \"dinam\"\n    metersPerUnit = 1\n"
      "    upAxis = \"Z\"\n    startTimeCode = 1\n    endTimeCode = {}\n"
      "    timeCodesPerSecond = {}\n    framesPerSecond = {}\n)\n\ndef Xform \"dinam\"\n{{\n",
      kVersion, frame_count_, fps_, fps_);
  for (const std::unique_ptr<Prim>& prim : prims_) {
    const bool mesh = prim->kind == Prim::Kind::kMesh;
    const ObjectLook& look = looks[static_cast<std::size_t>(prim->object)];
    put("    def {} \"{}\" (\n        prepend apiSchemas = [\"MaterialBindingAPI\"]\n",
        mesh ? "Mesh" : "BasisCurves", prim->name);
    if (!prim->display_name.empty()) {
      put("        displayName = \"{}\"\n", usd_string(prim->display_name));
    }
    put("    )\n    {{\n        rel material:binding = </dinam/{}/{}>\n", kLooksScope, prim->name);
    const auto put_int = [&](Index v) { put("{}", v); };
    if (mesh) {
      put("        uniform token subdivisionScheme = \"none\"\n        int[] faceVertexCounts = ");
      append_array(text, prim->counts, put_int);
      put("\n        int[] faceVertexIndices = ");
      append_array(text, prim->indices, put_int);
      put("\n");
      if (!prim->uvs.empty()) {
        put("        texCoord2f[] primvars:st = ");
        append_array(text, prim->uvs,
                     [&](const Eigen::Vector2f& uv) { put("({}, {})", uv.x(), uv.y()); });
        put(" (\n            interpolation = \"faceVarying\"\n        )\n"
            "        int[] primvars:st:indices = ");
        append_array(text, prim->uv_indices, put_int);
        put("\n");
      }
    } else {
      put("        uniform token type = \"linear\"\n        int[] curveVertexCounts = ");
      append_array(text, prim->counts, put_int);
      put("\n        float[] widths = [{}] (\n            interpolation = \"constant\"\n        "
          ")\n",
          2.0f * look.wire_radius);
      put("        int[] primvars:dinam:node = ");
      append_array(text, prim->nodes, [&](Index node) { put("{}", node - prim->first_node); });
      put(" (\n            interpolation = \"vertex\"\n        )\n");
    }
    put("        color3f[] primvars:displayColor = [({}, {}, {})] (\n"
        "            interpolation = \"constant\"\n        )\n",
        prim->color.x(), prim->color.y(), prim->color.z());
    put("        float3[] extent.timeSamples = {{\n");
    for (std::size_t f = 0; f < prim->extents.size(); ++f) {
      put("            {}: [", f + 1);
      append_point(text, prim->extents[f][0]);
      put(", ");
      append_point(text, prim->extents[f][1]);
      put("],\n");
    }
    put("        }}\n        point3f[] points.timeSamples = {{\n");
    write_text(out, text, file.temporary_path());
    text.clear();
    // The samples, as add_frame wrote them.
    if (std::fclose(prim->samples) != 0) {
      prim->samples = nullptr;
      throw_write_error(prim->samples_path);
    }
    prim->samples = nullptr;
    std::FILE* in = std::fopen(prim->samples_path.c_str(), "rb");
    if (in == nullptr) {
      throw_write_error(prim->samples_path);
    }
    std::array<char, 1 << 16> buffer{};
    std::size_t read = 0;
    while ((read = std::fread(buffer.data(), 1, buffer.size(), in)) > 0) {
      if (std::fwrite(buffer.data(), 1, read, out) != read) {
        std::fclose(in);
        throw_write_error(file.temporary_path());
      }
    }
    std::fclose(in);
    std::filesystem::remove(prim->samples_path);
    put("        }}\n    }}\n");
  }
  put("    def Scope \"{}\"\n    {{\n", kLooksScope);
  for (const std::unique_ptr<Prim>& prim : prims_) {
    append_material(text, *prim, looks[static_cast<std::size_t>(prim->object)].finish);
  }
  put("    }}\n}}\n");
  write_text(out, text, file.temporary_path());
  file.commit();
}

}  // namespace dinam

#pragma once
// The motion as a USD stage in its text form (.usda), for Houdini, Maya, Omniverse and Blender
// builds with USD: one prim per object under /dinam, its points sampled at every frame.
//  - An object drawn as a surface is a Mesh of its faces (no subdivision), with its texture
//    coordinates as face-varying primvars:st with indices (a UV seam keeps a pair on each side);
//    its bars on no face (a flag's ropes) are a BasisCurves prim beside it, "<name>_wires".
//  - An object drawn as wires is a BasisCurves prim of all its bars, linear, with the width it is
//    drawn with (style `both`: the Mesh and the BasisCurves of all bars). Bars are chained into
//    polylines where a node joins exactly two of them; each curve vertex names its node in
//    `primvars:dinam:node` (the object's vertex id, as in its OBJ and point caches), since a node
//    where curves meet is a vertex of each.
//  - Every prim is bound to a Material of its own under /dinam/Looks: a UsdPreviewSurface of the
//    object's colour, or of its texture (the cache's copy beside the stage, referenced
//    relatively), with its finish's roughness and metalness. A prim whose name is not
//    the object's keeps the object's as its displayName.
//  - Time code k is frame k (1-based), at timeCodesPerSecond = the scene's fps; Z up, metres.
// Points are float32 and written so that they read back as the same values as the point caches.
// A bar that breaks (tearing) stays in the stage: USD's topology here does not change in time.
//
// The frames arrive one at a time, but USD keeps each attribute's samples together, so each
// prim's samples go to a file of their own beside the stage while the run goes, and write()
// joins them into the stage after the last frame: memory stays one frame's worth.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cache/manifest.hpp"
#include "core/types.hpp"

namespace dinam {

struct Model;

class UsdStageWriter {
 public:
  // Opens the sample files in `folder` (the cache's temporary folder). `looks` holds how the
  // scene draws each object, which decides its prims (and names each texture's copy in the
  // folder); their radii may still be 0 here (they are given to write()).
  UsdStageWriter(std::filesystem::path folder, std::string file_name, const Model& model,
                 const std::vector<ObjectLook>& looks, double fps, int frame_count);
  ~UsdStageWriter();
  UsdStageWriter(const UsdStageWriter&) = delete;
  UsdStageWriter& operator=(const UsdStageWriter&) = delete;

  // Adds the next frame: every node's position.
  void add_frame(const std::vector<Vec3f>& positions);

  // After the last frame: writes the stage (with the drawn radii of `looks`) and removes the
  // sample files. Throws WriteError when a file cannot be written.
  void write(const std::vector<ObjectLook>& looks);

  const std::string& file_name() const { return file_name_; }

  struct Prim;  // one Mesh or BasisCurves prim (usd_stage.cpp)

 private:
  std::filesystem::path folder_;
  std::string file_name_;
  double fps_ = 0.0;
  int frame_count_ = 0;
  int frames_written_ = 0;
  std::vector<std::unique_ptr<Prim>> prims_;
};

// A USD prim name for an object name: letters, digits and '_' kept, any other character made
// '_', and a leading '_' added before a digit or for an empty name.
std::string usd_prim_name(const std::string& object_name);

}  // namespace dinam

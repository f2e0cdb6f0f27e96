#pragma once
// GLSL programs read from files in shaders/. The folder is looked up, in order: $DINAM_SHADER_DIR,
// `shaders/` beside the program, `../share/dinam/shaders` from the program (an installed tree),
// and the source tree's shaders/ (a build that was never installed).
#include <filesystem>
#include <string>
#include <vector>

namespace dinam {

// The folders searched, in order, whether or not they exist.
std::vector<std::filesystem::path> shader_search_path();

// The first folder of shader_search_path() that holds `file`; throws RuntimeError listing every
// folder tried when none does.
std::filesystem::path find_shader(const std::string& file);

class ShaderProgram {
 public:
  // Compiles and links the two files; throws RuntimeError naming the file and the GLSL log.
  // `fragment_includes` are spliced into the fragment shader after its #version line, in order
  // (GLSL has no #include), after the `fragment_defines` ("#define NAME" lines): choices made
  // when the program is built cost nothing per pixel, where a branch on a uniform costs much in
  // Mesa's software rasteriser.
  ShaderProgram(const std::string& vertex_file, const std::string& fragment_file,
                const std::vector<std::string>& fragment_includes = {},
                const std::string& fragment_defines = "");
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  int uniform(const char* name) const;  // location, −1 if the shader does not use it

 private:
  unsigned id_ = 0;
};

}  // namespace dinam

#include "render/shader_program.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <unistd.h>

#include <array>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace dinam {
namespace {

std::filesystem::path executable_folder() {
  std::array<char, 4096> buffer{};
  const ssize_t n = readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
  if (n <= 0) {
    return {};
  }
  return std::filesystem::path(std::string(buffer.data(), static_cast<std::size_t>(n)))
      .parent_path();
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw RuntimeError(fmt::format("cannot read shader file {}", path.string()));
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

unsigned compile(GLenum kind, const std::string& file, const std::vector<std::string>& includes,
                 const std::string& defines) {
  const std::filesystem::path path = find_shader(file);
  std::string source = read_text(path);
  if (!includes.empty() || !defines.empty()) {
    const std::size_t first_line_end = source.find('\n') + 1;
    std::string spliced = source.substr(0, first_line_end) + defines;
    for (const std::string& include : includes) {
      spliced += read_text(find_shader(include)) + "\n";
    }
    source = spliced + source.substr(first_line_end);
  }
  const GLuint shader = glCreateShader(kind);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == 0) {
    std::array<char, 4096> log{};
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    throw RuntimeError(fmt::format("shader {} does not compile:\n{}", path.string(), log.data()));
  }
  return shader;
}

}  // namespace

std::vector<std::filesystem::path> shader_search_path() {
  std::vector<std::filesystem::path> folders;
  if (const char* env = std::getenv("DINAM_SHADER_DIR"); env != nullptr && *env != '\0') {
    folders.emplace_back(env);
  }
  const std::filesystem::path exe = executable_folder();
  if (!exe.empty()) {
    folders.push_back(exe / "shaders");
    folders.push_back(exe.parent_path() / "share" / "dinam" / "shaders");
  }
  folders.emplace_back(DINAM_SOURCE_SHADER_DIR);
  return folders;
}

std::filesystem::path find_shader(const std::string& file) {
  std::string tried;
  for (const auto& folder : shader_search_path()) {
    std::filesystem::path candidate = folder / file;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) {
      return candidate;
    }
    tried += "\n  " + candidate.string();
  }
  throw RuntimeError(fmt::format(
      "shader file '{}' not found; looked at:{}\nSet DINAM_SHADER_DIR to the folder that holds "
      "dinam's shaders/",
      file, tried));
}

ShaderProgram::ShaderProgram(const std::string& vertex_file, const std::string& fragment_file,
                             const std::vector<std::string>& fragment_includes,
                             const std::string& fragment_defines) {
  const unsigned vertex = compile(GL_VERTEX_SHADER, vertex_file, {}, "");
  unsigned fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, fragment_file, fragment_includes, fragment_defines);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok == 0) {
    std::array<char, 4096> log{};
    glGetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteProgram(id_);
    throw RuntimeError(
        fmt::format("shaders {} and {} do not link:\n{}", vertex_file, fragment_file, log.data()));
  }
}

ShaderProgram::~ShaderProgram() {
  glDeleteProgram(id_);
}

void ShaderProgram::use() const {
  glUseProgram(id_);
}

int ShaderProgram::uniform(const char* name) const {
  return glGetUniformLocation(id_, name);
}

}  // namespace dinam

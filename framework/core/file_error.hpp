// The error of a file that cannot be read or written (core/file_read.hpp,
// core/atomic_file.hpp): what() is "<path>: <problem>", and both parts are
// kept so a caller can put the problem into its own wording.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace corrmp {

class FileError : public std::runtime_error {
 public:
  FileError(std::string path, std::string problem)
      : std::runtime_error(path + ": " + problem),
        path_(std::move(path)),
        problem_(std::move(problem)) {}

  const std::string& path() const { return path_; }
  // What is wrong, without the path: "is a directory", "cannot write: No space left on device".
  const std::string& problem() const { return problem_; }

 private:
  std::string path_;
  std::string problem_;
};

}  // namespace corrmp

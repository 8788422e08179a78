#include "experiment/input_files.h"

#include "common/file_io.h"

namespace echoplan::experiment {

const std::string& InputFiles::text(const std::string& path) {
  auto it = texts_.find(path);
  if (it == texts_.end()) it = texts_.emplace(path, read_text_file(path, "file")).first;
  return it->second;
}

std::shared_ptr<const pomdp::Problem> InputFiles::problem(const std::string& path) {
  auto it = problems_.find(path);
  if (it == problems_.end())
    it =
        problems_
            .emplace(path,
                     std::make_shared<const pomdp::Problem>(pomdp::parse_problem(text(path), path)))
            .first;
  return it->second;
}

}  // namespace echoplan::experiment

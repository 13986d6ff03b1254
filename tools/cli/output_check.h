#pragma once
#include <string>
#include <vector>

namespace mvpl::cli {

// Before any rendering starts, so that a bad -o costs nothing: each output's extension is .exr or
// .png (UsageError), its folder exists and is writable, and it is not itself a folder
// (InputError naming the path).
void check_outputs(const std::vector<std::string>& outputs);

// Creates the output folder `folder` and its parents (convergence --out); throws InputError
// naming it when it cannot be a folder (it or a parent is a file, or may not be written).
void create_output_folder(const std::string& folder);

// Without -o a command writes `fallback`: returns `outputs`, or {fallback} when it is empty.
// `defaulted` tells the command to say where the image went once it is written
// (say_written), so that a user who gave no -o learns the file's name.
std::vector<std::string> outputs_or(const std::vector<std::string>& outputs,
                                    const std::string& fallback, bool& defaulted);
// "COMMAND: wrote PATH" on stdout when the output was defaulted and the command is not quiet.
void say_written(const std::string& command, const std::vector<std::string>& outputs,
                 bool defaulted, bool quiet);

}  // namespace mvpl::cli

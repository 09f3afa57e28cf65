// Learner run folders: where a run's files are (the folder itself, or one folder per learner
// below it) and the text summary printed after a run.
#ifndef STRIDE_STUDY_RUN_FOLDER_HPP
#define STRIDE_STUDY_RUN_FOLDER_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace stride::study {

/// `dir` and its subfolders (sorted, without figures/): where learners write their files.
std::vector<std::filesystem::path> run_folders(const std::filesystem::path& dir);

/// Whether `dir` (or a folder right below it) holds a learner's V table or evaluation.
bool has_learner_artefacts(const std::filesystem::path& dir);

/// Text summary of the run for the terminal: best.txt of each learner, the evaluation table.
std::string summarize_run(const std::filesystem::path& dir);

}  // namespace stride::study

#endif  // STRIDE_STUDY_RUN_FOLDER_HPP

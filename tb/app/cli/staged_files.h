// A run's output files, staged under temporary names inside --out DIR and
// renamed into place only when the whole run succeeded (docs/cli.md): a
// failed run leaves no report.json, frames.csv or any other file of its own.
//
// Staging folder: DIR/.stereosim-staging-<pid>/ (same file system as DIR, so
// each rename(2) is atomic). commit() renames every staged file to
// DIR/<relative path> (creating subfolders such as waves/) and removes the
// staging folder; the destructor removes it if commit() did not run.
#pragma once

#include <string>
#include <vector>

namespace cli {

class staged_files {
  public:
    staged_files() = default;
    ~staged_files();
    staged_files(const staged_files&) = delete;
    staged_files& operator=(const staged_files&) = delete;

    // Creates DIR (and parents) and the staging folder inside it; false and
    // *error (one line) if DIR cannot be created or written.
    bool open(const std::string& dir, std::string* error);

    // Where to write the file that will become DIR/relative; creates the
    // staging subfolders. Records it for commit().
    std::string staged_path(const std::string& relative);

    // Renames every staged file into DIR. false + *error if a rename failed.
    bool commit(std::string* error);
    // Removes the staging folder and whatever is in it.
    void discard();

    const std::string& dir() const { return m_dir; }
    // The final paths commit() made, in staging order.
    const std::vector<std::string>& committed() const { return m_committed; }

  private:
    std::string m_dir;
    std::string m_staging;
    std::vector<std::string> m_relative;
    std::vector<std::string> m_committed;
};

}  // namespace cli

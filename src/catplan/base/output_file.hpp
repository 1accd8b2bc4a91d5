#pragma once
// Output files are written whole or not at all. A regular file (new, or replaced) is written to a
// temporary file in its directory, which is then renamed over it, so a failed run never leaves a
// partial file; a new file gets the usual mode (0666 less the umask, as the shell's `>` gives), a
// replaced one keeps its mode (and, for root, its owner). A symlink is followed: the file it points
// to is replaced, the link stays. A target that is not a regular file (a device such as /dev/null,
// a FIFO, or /dev/stdout and the other /proc/self/fd links) is written in place and never
// replaced. A directory is an error.
//
// The files of one command form an OutputSet: every one is staged (written in full beside its
// target, each target checked) before the first is put in place, so that a command either writes
// all its outputs or none.
//
//   OutputSet out;
//   if (!out.stage("d.pddl", domain, why) || !out.stage("p.pddl", problem, why) ||
//       !out.commit(why)) { report(why); }   // nothing written unless all of it could be

#include <string>
#include <string_view>
#include <vector>

namespace catplan {

/// The files one command writes, put in place all together by commit().
class OutputSet {
public:
    OutputSet() = default;
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    /// Removes the temporary files of a set that was not committed.
    ~OutputSet();

    /// Checks the target `path` and writes `contents` beside it (or, for a target written in place,
    /// opens it); false with `error` set, and nothing at any target touched, when it cannot.
    bool stage(const std::string& path, std::string_view contents, std::string& error);

    /// Puts every staged file in place (in-place targets first, then the renames); false with
    /// `error` set when one could not be. A set is committed at most once.
    bool commit(std::string& error);

private:
    struct Staged {
        std::string target;    ///< the file replaced or written (a symlink resolved)
        std::string temporary; ///< "" for a target written in place
        int fd = -1;           ///< an in-place target, open for writing
        std::string contents;  ///< what an in-place target receives at commit
    };

    std::vector<Staged> staged_;
    bool committed_ = false;
};

/// Writes contents to path as a one-file OutputSet; on failure returns false and sets error,
/// leaving any existing file at path untouched.
bool write_file_atomically(const std::string& path, std::string_view contents, std::string& error);

} // namespace catplan

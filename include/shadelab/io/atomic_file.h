// Every file shadelab writes goes through here, so every output follows one set of rules (README "Output
// files"):
//   - a regular file (new or existing) is written to a temporary file ".shadelab-XXXXXX" beside it, flushed
//     to disk, then renamed over it: it appears whole or not at all, and a replaced file keeps its mode and
//     owner (replacement makes a new inode, so hard links to the old file keep the old content);
//   - a symbolic link is followed, and its target is replaced that way (the link stays a link);
//   - "-" is standard output, and a character device or FIFO is written through directly (no temporary
//     file): `--out /dev/null` works, `/dev/full` fails with the OS error, a FIFO's reader gets the file;
//   - /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N are this process's open descriptor, written
//     through as "-" is (never the file behind it replaced: a log opened for appending keeps its lines);
//   - a symbolic link in a sticky world-writable folder (/tmp) that belongs to neither the caller nor the
//     folder's owner is refused, as the kernel's fs.protected_symlinks refuses to follow it;
//   - an existing file the caller may not write, or a folder where the caller may not create the
//     temporary file, is refused before any work;
//   - a folder, block device or socket is refused (InputError) before any work is done;
//   - the content is produced completely in memory or in the temporary file first, so a failure while
//     producing it never touches the output; a write, flush, fsync or close that fails is an error;
//   - SIGINT, SIGTERM and SIGHUP remove the live temporary files, then end the process by that signal.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab {

// Where an output path really goes, resolved once before any work.
struct OutputTarget {
    enum class Kind {
        Stdout,       // "-"
        Regular,      // an existing regular file or a new one: temporary file, then rename
        WriteThrough, // a character device or a FIFO: opened and written directly
        Descriptor    // /dev/stdout, /dev/fd/N…: this process's open descriptor, written directly
    };
    Kind kind = Kind::Regular;
    std::filesystem::path path; // symbolic links resolved; empty for Stdout; as given for Descriptor
    std::string field;          // the argument that named it, for messages ("--out")
    int descriptor = -1;        // Descriptor: the open descriptor
};

// Throws InputError naming `field`, the path and the fix for an empty path, a folder, a block device, a
// socket, a missing folder, a loop of symbolic links, a link the kernel would not follow, a descriptor that
// is not open for writing, or a file or folder the caller may not write.
OutputTarget resolveOutput(const std::filesystem::path& userPath, std::string_view field);

// How an output path is taken: as resolveOutput's rules say (links followed, devices and FIFOs written
// through), or as a file of a folder of outputs (report --out, slides --out-dir): created inside its folder,
// replacing only a regular file there and never through a symbolic link, so nothing planted in the folder
// (a link to an input or to /dev/null, a FIFO that would block) can redirect or swallow it.
enum class OutputRule { Anywhere, InFolder };

// resolveOutput for a file of a folder of outputs (OutputRule::InFolder): `dir`/`name` if nothing is there
// yet or a regular file the caller may replace is; a symbolic link, FIFO, device, socket or folder there is
// refused with an InputError naming `field`, the path and the fix.
OutputTarget resolveFolderEntry(const std::filesystem::path& dir, const std::string& name,
                                std::string_view field);

// A folder that several outputs are written into (report --out, slides --out-dir), checked before any work:
// created if missing (with its parents); refused with an InputError naming `field` when it is not a folder,
// cannot be created or cannot take a new file, or when any of `names` in it could not be an output
// (resolveFolderEntry's rules) or is one of `inputs`.
void prepareOutputFolder(const std::filesystem::path& dir, std::string_view field,
                         const std::vector<std::string>& names,
                         const std::vector<std::filesystem::path>& inputs);

// Throws InputError when the output `out` (named by `field`) writes where standard output goes while
// standard output carries text (`carries`: "the matrices of --print-matrices"): "-", /dev/stdout,
// /dev/fd/1, /proc/self/fd/1, another descriptor or a path open on the same file or pipe. The null device
// is allowed (nothing there can mix).
// The message's fix names a file like `example`.
void refuseStandardOutputAlias(const std::filesystem::path& out, std::string_view field,
                               std::string_view carries, std::string_view example = "FILE.png");

// True when both paths name the same existing file (device and inode, after following links).
bool isSameFile(const std::filesystem::path& a, const std::filesystem::path& b);

// Throws InputError when `output` (as `field` names it) is the input file `input`: writing would destroy it.
void refuseOverwritingInput(const std::filesystem::path& output, std::string_view field,
                            const std::filesystem::path& input);

// One output being written: fill stream(), then finish() and commit(). Destroyed before commit(), it leaves
// the target as it was and removes its temporary file.
class PendingOutput {
public:
    // `what` names the content in messages ("PNG").
    PendingOutput(OutputTarget target, std::string_view what);
    PendingOutput(PendingOutput&&) noexcept;
    PendingOutput& operator=(PendingOutput&&) noexcept;
    ~PendingOutput();

    std::FILE* stream() const;
    // Flushes and closes the content: a regular file is fsynced; a write-through output's bytes are held.
    void finish();
    // Puts the content in place: renames the temporary file, or writes the held bytes to the device, FIFO
    // or standard output. Throws RuntimeError "cannot write <what> "<path>": <reason>".
    void commit();
    const OutputTarget& target() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// Finishes every output, then commits them one after the other with SIGINT/SIGTERM/SIGHUP held back, so
// a failure or a signal before the renames leaves every old file as it was.
void commitAll(std::vector<PendingOutput>& outputs);

// Resolves `path` (field `what`) by `rule`, lets `write` fill the content, and commits it.
void writeFileAtomically(const std::filesystem::path& path, std::string_view what,
                         const std::function<void(std::FILE*)>& write,
                         OutputRule rule = OutputRule::Anywhere);

// Throws RuntimeError "cannot write <what> "<path>": <reason>".
[[noreturn]] void failWrite(std::string_view what, const std::filesystem::path& path,
                            const std::string& reason);

// SIGINT, SIGTERM and SIGHUP (unless ignored): remove the live temporary files, then re-raise the signal
// with its default action, so the exit status says what happened. Call once at start-up.
void installOutputSignalHandlers();

} // namespace shadelab

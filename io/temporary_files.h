/// @file io/temporary_files.h
/// @brief The temporary files being written right now, so that SIGINT, SIGTERM or SIGHUP
/// arriving mid-write removes them instead of leaving a hidden half file beside the target.
/// The registry is a fixed table of plain character buffers: the signal handler reads it with
/// async-signal-safe calls only (unlink, then the signal re-raised with its default action).
#pragma once

#include <string>

namespace kerf {

/// One registered temporary. Registered before the file is created and released after it is
/// renamed or removed, so no moment exists when the file is on disk unregistered. The
/// handlers are installed on first use, only for signals whose action is still the default
/// (a shell that ignores SIGINT for a background job keeps it ignored).
class InFlightTemporary {
public:
    /// Registers `path` (made absolute first: the handler must not depend on the working
    /// folder). When the table is full or the path too long, the file is simply not guarded.
    explicit InFlightTemporary(const std::string& path);
    ~InFlightTemporary();
    InFlightTemporary(const InFlightTemporary&) = delete;
    InFlightTemporary& operator=(const InFlightTemporary&) = delete;

private:
    int mSlot = -1;
};

}  // namespace kerf

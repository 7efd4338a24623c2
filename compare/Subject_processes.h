// The processes of external subjects end with the run, and so does
// everything they start (issue 59 item 7), on every exit path:
// - each subject is a process group of its own, killed whole when closed;
// - the subject dies with clash4d (a parent-death signal), even on kill -9;
// - clash4d is a child subreaper, so a subject's descendant that left the
//   group (setsid) comes back to clash4d when its parent dies, and is killed
//   and reaped there; it is known by a mark in its environment
//   (CLASH4D_SUBJECT_OF=<clash4d's pid>), zombies by being children nobody
//   else waits for;
// - SIGTERM, SIGINT and SIGHUP (when not ignored) kill every subject and
//   its descendants, then end clash4d by the same signal.
// The guards are Linux's; elsewhere the groups are still killed on close.
// Left: after kill -9 of clash4d, a descendant that had left the subject's
// group outlives it (only a cgroup would hold it).
#ifndef CLASH4D_COMPARE_SUBJECT_PROCESSES_H
#define CLASH4D_COMPARE_SUBJECT_PROCESSES_H

#include <string>
#include <sys/types.h>
#include <vector>

namespace clash4d::subject_processes {

// Forks and execs `/bin/sh -c command` with `in` and `out` as its standard
// input and output, in a process group of its own; the leader's pid (also
// its group's id), or -1 with errno set (ECANCELED once clash4d is ending
// on a signal).
pid_t start(const std::string& command, int in, int out);

// Ends a subject: kills its group, reaps the leader (its wait status into
// `status` unless `reaped` says it already was), then kills and reaps every
// descendant that came back to clash4d, until none is left (bounded).
void end(pid_t leader, bool reaped, int& status);

// Makes this process the keeper of its subjects' descendants: a child
// subreaper that kills and reaps what comes back to it (zombies included)
// and the SIGTERM, SIGINT and SIGHUP handlers above. For a program that
// owns all of its children, as the clash4d command does (cli/main.cpp); a
// program that embeds the library and waits for children of its own
// (Python's subprocess) must not call it, and then only the subjects'
// groups are killed.
void keep_descendants();

} // namespace clash4d::subject_processes

#endif

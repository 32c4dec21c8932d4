// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An X display for off-screen OpenGL: the one in DISPLAY if it opens, else a private Xvfb
// started once per process (Xvfb -displayfd picks a free display number and writes it back;
// -noreset: a server that resets when its last client leaves refuses connections meanwhile),
// stopped when the process exits.  VTK's X render window aborts without a display, so the
// demo's renderer (render_surface_PNG.h) asks here first; the library itself starts no
// processes.  FAS_NO_XVFB=1 in the environment forbids starting Xvfb.

#ifndef FAS_DEMO_VIRTUAL_DISPLAY_H
#define FAS_DEMO_VIRTUAL_DISPLAY_H

#include <csignal>
#include <cstdlib>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

// The two calls of libX11 needed here, declared as <X11/Xlib.h> declares them: including Xlib.h
// would define macros such as Success and None that break Eigen and CGAL code after it.
extern "C" {
struct _XDisplay;
_XDisplay* XOpenDisplay(const char*);
int XCloseDisplay(_XDisplay*);
}

namespace fas_demo {

inline bool display_opens(const char* name)
{
  if (name == nullptr || *name == '\0')
    return false;
  _XDisplay* display = XOpenDisplay(name);
  if (display == nullptr)
    return false;
  XCloseDisplay(display);
  return true;
}

/// The Xvfb this process started, terminated at exit.
struct Private_xvfb {
  pid_t pid = -1;
  std::string failure; // why it could not be started, if it could not
  ~Private_xvfb()
  {
    if (pid > 0) {
      ::kill(pid, SIGTERM);
      ::waitpid(pid, nullptr, 0);
    }
  }
};

/// Starts Xvfb and returns its display name (":N"), or an empty string with `failure` set.
inline std::string start_xvfb(Private_xvfb& xvfb)
{
  int fds[2];
  if (::pipe(fds) != 0) {
    xvfb.failure = "pipe() failed";
    return {};
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    xvfb.failure = "fork() failed";
    return {};
  }
  if (pid == 0) {
    ::close(fds[0]);
    const int null = ::open("/dev/null", O_RDWR);
    if (null >= 0) {
      ::dup2(null, STDIN_FILENO);
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    const std::string fd = std::to_string(fds[1]);
    execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-nolisten", "tcp", "-noreset", "-screen", "0",
           "1280x1024x24", static_cast<char*>(nullptr));
    _exit(127);
  }
  ::close(fds[1]);
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  // Xvfb writes the display number once it accepts connections: 20 s is generous on a loaded machine.
  while (::poll(&p, 1, 20000) > 0) {
    char c;
    if (::read(fds[0], &c, 1) != 1 || c == '\n')
      break;
    number += c;
  }
  ::close(fds[0]);
  if (number.empty()) {
    ::kill(pid, SIGTERM);
    int status = 0;
    ::waitpid(pid, &status, 0);
    xvfb.failure = WIFEXITED(status) && WEXITSTATUS(status) == 127
                       ? "Xvfb is not installed (Debian: xvfb)"
                       : "Xvfb did not report a display within 20 s";
    return {};
  }
  xvfb.pid = pid;
  return ":" + number;
}

/// Makes sure DISPLAY names a display that opens; returns false with the reason otherwise.
inline bool ensure_display(std::string& reason)
{
  if (display_opens(std::getenv("DISPLAY")))
    return true;
  static Private_xvfb xvfb;
  static const std::string started = [] {
    const char* forbid = std::getenv("FAS_NO_XVFB");
    if (forbid != nullptr && std::string(forbid) == "1") {
      xvfb.failure = "starting Xvfb is disabled (FAS_NO_XVFB=1)";
      return std::string();
    }
    return start_xvfb(xvfb);
  }();
  if (!started.empty() && display_opens(started.c_str())) {
    setenv("DISPLAY", started.c_str(), 1);
    return true;
  }
  const char* display = std::getenv("DISPLAY");
  reason =
      "no X display to render with (DISPLAY=" + std::string(display ? display : "") +
      " does not open) and no Xvfb: " + (xvfb.failure.empty() ? "its display does not open" : xvfb.failure);
  return false;
}

} // namespace fas_demo

#endif // FAS_DEMO_VIRTUAL_DISPLAY_H

// dinam owns SIGINT and SIGTERM: no library may take them over.
//
// METIS (which CHOLMOD calls to order a factorisation: `info`'s estimate of an implicit run, and
// the implicit integrator's analysis of a large Hessian) traps SIGTERM for the length of each
// ordering with its own handler, which longjmps out of METIS and returns an error: a SIGTERM that
// landed there was swallowed, and the run went on to its end (the signal stress test caught it,
// a render stopped 63 ms in that never stopped). METIS installs it through glibc's
// `__sysv_signal`; the program defines that function (exported, so it interposes for every
// library, as a replaced malloc does) and leaves SIGINT and SIGTERM as dinam set them: a request
// to stop then reaches dinam's handler (app/command_support.hpp) or the default action. Every
// other signal is set as glibc's own System V `signal` sets it.
#include <signal.h>

extern "C" __sighandler_t __sysv_signal(int signal_number, __sighandler_t handler) noexcept {
  struct sigaction previous {};
  if (signal_number == SIGINT || signal_number == SIGTERM) {
    sigaction(signal_number, nullptr, &previous);
    return previous.sa_handler;
  }
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_NODEFER;  // System V's: one shot, not blocked within
  if (sigaction(signal_number, &action, &previous) < 0) {
    return SIG_ERR;
  }
  return previous.sa_handler;
}

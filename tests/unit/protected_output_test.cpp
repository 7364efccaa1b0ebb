// While a ProtectedOutput lives, what the process prints to standard output (as OCCT's
// diagnostics do) goes to standard error, and only the answers reach standard output; after
// it, standard output is the original again.
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "airshape/protected_output.h"

namespace airshape {
namespace {

/// Everything written to a pipe's write end so far, the write end closed.
std::string drained(int pipe[2]) {
  ::close(pipe[1]);
  std::string text;
  char chunk[256];
  for (ssize_t n; (n = ::read(pipe[0], chunk, sizeof chunk)) > 0;) text.append(chunk, static_cast<std::size_t>(n));
  ::close(pipe[0]);
  return text;
}

TEST(ProtectedOutput, StrayPrintsGoToStandardErrorAndAnswersToStandardOutput) {
  int out[2], err[2];
  ASSERT_EQ(::pipe(out), 0);
  ASSERT_EQ(::pipe(err), 0);
  std::cout.flush();
  std::fflush(stdout);
  std::fflush(stderr);
  const int savedOut = ::dup(STDOUT_FILENO), savedErr = ::dup(STDERR_FILENO);
  ::dup2(out[1], STDOUT_FILENO);
  ::dup2(err[1], STDERR_FILENO);
  ::close(out[1]);
  ::close(err[1]);
  out[1] = ::dup(STDOUT_FILENO);
  err[1] = ::dup(STDERR_FILENO);
  {
    ProtectedOutput output;
    std::printf("Division par zero\n");
    std::fflush(stdout);
    std::cout << "a library's line" << std::endl;
    output.answers() << "{\"ok\":1}\n" << std::flush;
  }
  std::printf("after\n");
  std::fflush(stdout);
  ::dup2(savedOut, STDOUT_FILENO);
  ::dup2(savedErr, STDERR_FILENO);
  ::close(savedOut);
  ::close(savedErr);
  const std::string answers = drained(out), errors = drained(err);
  EXPECT_EQ(answers, "{\"ok\":1}\nafter\n");
  EXPECT_EQ(errors, "Division par zero\na library's line\n");
}

}  // namespace
}  // namespace airshape

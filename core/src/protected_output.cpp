#include "airshape/protected_output.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <vector>

namespace airshape {

namespace {

/// A stream buffer writing to a file descriptor, emptied on every flush.
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int descriptor) : descriptor_(descriptor), buffer_(4096) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  ~DescriptorBuffer() override { sync(); }

 protected:
  int_type overflow(int_type character) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(character, traits_type::eof())) sputc(traits_type::to_char_type(character));
    return traits_type::not_eof(character);
  }

  int sync() override {
    for (const char* next = pbase(); next < pptr();) {
      const ssize_t written = ::write(descriptor_, next, static_cast<std::size_t>(pptr() - next));
      if (written <= 0) return -1;
      next += written;
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return 0;
  }

 private:
  int descriptor_;
  std::vector<char> buffer_;
};

}  // namespace

ProtectedOutput::ProtectedOutput() : answers_(std::cout.rdbuf()) {
  std::cout.flush();
  std::fflush(stdout);
  original_ = ::dup(STDOUT_FILENO);
  if (original_ < 0) return;
  if (::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
    ::close(original_);
    original_ = -1;
    return;
  }
  buffer_ = std::make_unique<DescriptorBuffer>(original_);
  answers_.rdbuf(buffer_.get());
}

ProtectedOutput::~ProtectedOutput() {
  answers_.flush();
  if (original_ < 0) return;
  std::cout.flush();
  std::fflush(stdout);
  buffer_.reset();
  ::dup2(original_, STDOUT_FILENO);
  ::close(original_);
}

}  // namespace airshape

// The fuzz targets' one helper: the input bytes as a file in a folder of this process's own
// (under $TMPDIR, else /dev/shm, else /tmp), written fresh for every input.  A detached data
// file can be fuzzed too: the bytes after the first "\n--DATA--\n" are also written to
// `data.raw` in the same folder (empty if there is no such line).

#ifndef FAS_FUZZ_INPUT_FILE_H
#define FAS_FUZZ_INPUT_FILE_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>

inline std::string fuzz_folder()
{
  static const std::string folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string base = tmp && *tmp ? tmp : (access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp");
    const std::string f = base + "/fas_fuzz_" + std::to_string(getpid());
    mkdir(f.c_str(), 0700);
    return f;
  }();
  return folder;
}

inline void fuzz_write(const std::string& file, std::string_view bytes)
{
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (f == nullptr)
    std::abort();
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size())
    std::abort();
  std::fclose(f);
}

// Writes the input (and data.raw) and returns the input's file name, ending in `extension`.
inline std::string fuzz_input_file(const std::uint8_t* data, std::size_t size, const char* extension)
{
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::string file = fuzz_folder() + "/input" + extension;
  fuzz_write(file, bytes);
  const std::size_t separator = bytes.find("\n--DATA--\n");
  fuzz_write(fuzz_folder() + "/data.raw",
             separator == std::string_view::npos ? std::string_view() : bytes.substr(separator + 10));
  return file;
}

#endif // FAS_FUZZ_INPUT_FILE_H

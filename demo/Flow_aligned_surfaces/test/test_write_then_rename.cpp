// The demo's files appear whole or not at all (write_then_rename.h): a write that fails, or a
// rename that cannot happen, leaves the earlier file as it was and no temporary behind.

#include "test_files.h"

#include "write_then_rename.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>

namespace {

using fas_demo::write_stream_then_rename;
using fas_demo::write_then_rename;

TEST(WriteThenRename, ReplacesTheFileWhenTheWriteSucceeds)
{
  const std::string file = temporary_file("write_then_rename_", "ok.txt");
  write_bytes(file, "earlier");
  std::string reason;
  ASSERT_TRUE(write_stream_then_rename(file, reason, [](std::ostream& os) { os << "new"; })) << reason;
  EXPECT_EQ(read_bytes(file), "new");
  EXPECT_FALSE(std::filesystem::exists(temporary_file("write_then_rename_", "ok.partial.txt")));
}

TEST(WriteThenRename, AFailedWriteKeepsTheEarlierFile)
{
  const std::string file = temporary_file("write_then_rename_", "failed.vtp");
  write_bytes(file, "earlier");
  std::string reason;
  std::string given;
  EXPECT_FALSE(write_then_rename(file, reason, [&](const std::string& temporary) {
    given = temporary;
    write_bytes(temporary, "half a fi");
    reason = "the writer stopped";
    return false;
  }));
  EXPECT_EQ(reason, "the writer stopped");
  EXPECT_EQ(given, temporary_file("write_then_rename_", "failed.partial.vtp")); // VTK goes by the extension
  EXPECT_EQ(read_bytes(file), "earlier");
  EXPECT_FALSE(std::filesystem::exists(given));
}

TEST(WriteThenRename, ARenameThatCannotHappenIsNamed)
{
  // A folder of that name cannot be replaced by a file.
  const std::string folder = temporary_file("write_then_rename_", "folder.txt");
  std::filesystem::create_directories(folder + "/inside");
  std::string reason;
  EXPECT_FALSE(write_stream_then_rename(folder, reason, [](std::ostream& os) { os << "new"; }));
  EXPECT_NE(reason.find("cannot rename " + temporary_file("write_then_rename_", "folder.partial.txt") +
                        " to " + folder),
            std::string::npos)
      << reason;
  EXPECT_TRUE(std::filesystem::is_directory(folder + "/inside"));
  EXPECT_FALSE(std::filesystem::exists(temporary_file("write_then_rename_", "folder.partial.txt")));
}

TEST(WriteThenRename, AFileThatCannotBeOpenedIsNamed)
{
  const std::string file = temporary_file("write_then_rename_", "no_such_folder/file.txt");
  std::string reason;
  EXPECT_FALSE(write_stream_then_rename(file, reason, [](std::ostream& os) { os << "new"; }));
  EXPECT_NE(
      reason.find("cannot open " + temporary_file("write_then_rename_", "no_such_folder/file.partial.txt")),
      std::string::npos)
      << reason;
}

} // namespace

// The one output policy (asperity/output.hpp): nothing planted is followed or opened, a file the
// run did not create is never replaced unless it is ours of that kind (or overwrite), an input
// is never written over, two outputs never share a file, and an error, an exception, Ctrl-C or
// SIGTERM leaves nothing half-written.
#include <gtest/gtest.h>
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "file_helpers.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/output.hpp"

namespace {
using asperity::Error;
using asperity::FolderEntry;
using asperity::OutputPlan;
using asperity::OutputTransaction;
namespace kinds = asperity::output_kinds;

using test_files::entries;
using test_files::plant;
using test_files::read_bytes;

std::string test_directory(const std::string& name) { return test_files::fresh_directory("output", name); }

std::string problem(const OutputPlan& plan) {
  try {
    plan.check();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

const std::string card_text = "** asperity 0.2.0: a card\n*SURFACE BEHAVIOR\n";

TEST(OutputPolicy, APlantedLinkIsNeverFollowed) {
  const std::string dir = test_directory("link");
  plant(dir + "/victim", "the user's");
  ASSERT_EQ(symlink((dir + "/victim").c_str(), (dir + "/card.inp").c_str()), 0);
  OutputPlan plan;
  plan.file("--card", dir + "/card.inp", kinds::card);
  EXPECT_NE(problem(plan).find("is a symbolic link, never followed"), std::string::npos) << problem(plan);
  EXPECT_THROW(asperity::write_output_file(dir + "/card.inp", card_text, kinds::card), Error);
  EXPECT_EQ(read_bytes(dir + "/victim"), "the user's");
  // with overwrite the link itself is replaced: its target is still not touched
  asperity::write_output_file(dir + "/card.inp", card_text, kinds::card, true);
  struct stat status {};
  ASSERT_EQ(lstat((dir + "/card.inp").c_str(), &status), 0);
  EXPECT_TRUE(S_ISREG(status.st_mode));
  EXPECT_EQ(read_bytes(dir + "/victim"), "the user's");
  EXPECT_EQ(read_bytes(dir + "/card.inp"), card_text);
}

TEST(OutputPolicy, AFifoOrDeviceIsNeverOpenedEvenWithOverwrite) {
  const std::string dir = test_directory("fifo");
  ASSERT_EQ(mkfifo((dir + "/table.h5").c_str(), 0600), 0);
  for (bool overwrite : {false, true}) {
    OutputPlan plan(overwrite);
    plan.file("--table", dir + "/table.h5", kinds::contact_curves_table);
    EXPECT_NE(problem(plan).find("a device, FIFO or socket"), std::string::npos);
  }
  // the folder form: a FIFO where a report file goes (the old writer hung opening it)
  OutputPlan plan;
  plan.folder("--fields", dir, {{"table.h5", &kinds::field_image}});
  EXPECT_NE(problem(plan).find("table.h5 is a device, FIFO or socket"), std::string::npos);
}

TEST(OutputPolicy, AFileNotOursOfThatKindIsKeptUnlessOverwrite) {
  const std::string dir = test_directory("kind");
  plant(dir + "/notes.inp", "my own notes\n");
  EXPECT_THROW(asperity::write_output_file(dir + "/notes.inp", card_text, kinds::card), Error);
  EXPECT_EQ(read_bytes(dir + "/notes.inp"), "my own notes\n");
  try {
    asperity::write_output_file(dir + "/notes.inp", card_text, kinds::card, false, "--card");
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("--card"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("not a pressure-overclosure card written by asperity"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("--overwrite"), std::string::npos);
  }
  // ours of the kind: replaced; with overwrite: anything regular
  asperity::write_output_file(dir + "/card.inp", card_text, kinds::card);
  asperity::write_output_file(dir + "/card.inp", card_text + "** again\n", kinds::card);
  EXPECT_EQ(read_bytes(dir + "/card.inp"), card_text + "** again\n");
  asperity::write_output_file(dir + "/notes.inp", card_text, kinds::card, true);
  EXPECT_EQ(read_bytes(dir + "/notes.inp"), card_text);
  // a card is not a table: a contact-curves table is not written over a card
  EXPECT_THROW(asperity::write_output_file(dir + "/card.inp", "x", kinds::contact_curves_table), Error);
  EXPECT_EQ(read_bytes(dir + "/card.inp"), card_text + "** again\n");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"card.inp", "notes.inp"}));
}

TEST(OutputPolicy, AnInputIsNeverWrittenOverHoweverItIsSpelled) {
  const std::string dir = test_directory("input");
  mkdir((dir + "/sub").c_str(), 0755);
  plant(dir + "/map.txt", "heights");
  ASSERT_EQ(link((dir + "/map.txt").c_str(), (dir + "/hard.txt").c_str()), 0);
  for (const std::string& spelling : {dir + "/map.txt", dir + "/sub/../map.txt", dir + "/./map.txt", dir + "/hard.txt"}) {
    OutputPlan plan(true);  // not even with overwrite
    plan.input(dir + "/map.txt");
    plan.file("--card", spelling, kinds::card);
    EXPECT_NE(problem(plan).find("is an input of this run"), std::string::npos) << spelling;
  }
  EXPECT_EQ(read_bytes(dir + "/map.txt"), "heights");
}

TEST(OutputPolicy, TwoOutputsOnOneFileAreRefusedBeforeAnyWork) {
  const std::string dir = test_directory("twice");
  OutputPlan plan;
  plan.file("--card", dir + "/x", kinds::card);
  plan.file("--table", dir + "/./x", kinds::contact_curves_table);
  EXPECT_NE(problem(plan).find("--table " + dir + "/./x: the same file as --card"), std::string::npos) << problem(plan);
  OutputPlan folder_and_file;
  folder_and_file.folder("--fields", dir, {{"step-1-gap.pgm", &kinds::field_image}});
  folder_and_file.file("--card", dir + "/step-1-gap.pgm", kinds::card);
  EXPECT_NE(problem(folder_and_file).find("the same file as --card"), std::string::npos) << problem(folder_and_file);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(OutputPolicy, MissingFoldersAndDirectoriesAreNamedWithTheReason) {
  const std::string dir = test_directory("missing");
  OutputPlan plan;
  plan.file("--card", dir + "/no/such/card.inp", kinds::card);
  EXPECT_NE(problem(plan).find("No such file or directory"), std::string::npos) << problem(plan);
  OutputPlan directory;
  directory.file("--card", dir, kinds::card);
  EXPECT_NE(problem(directory).find("is a directory"), std::string::npos);
  plant(dir + "/file", "x");
  OutputPlan under_a_file;
  under_a_file.folder("--fields", dir + "/file/deeper", {{"a.pgm", &kinds::field_image}});
  EXPECT_NE(problem(under_a_file).find("is not a directory"), std::string::npos) << problem(under_a_file);
}

TEST(OutputPolicy, NothingIsLeftWithoutCommit) {
  const std::string dir = test_directory("rollback");
  plant(dir + "/card.inp", card_text);
  {
    OutputPlan plan;
    plan.file("--card", dir + "/card.inp", kinds::card);
    plan.folder("--fields", dir + "/new/fields", {{"a.pgm", &kinds::field_image}});
    OutputTransaction outputs(plan);
    outputs.stage(dir + "/card.inp", "** asperity: the new card\n");
    outputs.stage(dir + "/new/fields", "a.pgm", "P5\n# asperity\n1 1\n65535\nxx");
    EXPECT_EQ(entries(dir).size(), 3u);  // card.inp, its temporary, new/
  }  // an error here: destroyed without commit
  EXPECT_EQ(entries(dir), std::vector<std::string>{"card.inp"});  // the folders it made are gone too
  EXPECT_EQ(read_bytes(dir + "/card.inp"), card_text);
}

TEST(OutputPolicy, AStopAskedBeforeTheCommitWritesNothing) {
  const std::string dir = test_directory("interrupted");
  bool stop = false;
  const asperity::InterruptScope scope([](void* flag) { return *static_cast<bool*>(flag); }, &stop);
  {
    OutputPlan plan;
    plan.file("--card", dir + "/card.inp", kinds::card);
    OutputTransaction outputs(plan);
    outputs.stage(dir + "/card.inp", card_text);
    stop = true;
    EXPECT_THROW(outputs.commit(), asperity::Interrupted);
  }
  EXPECT_THROW(asperity::write_output_file(dir + "/other.inp", card_text, kinds::card), asperity::Interrupted);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(OutputPolicy, AFolderKeepsTheUsersFilesAndDropsOnlyOursNotWrittenAgain) {
  const std::string dir = test_directory("folder");
  plant(dir + "/curves.csv", "my,own,curves\n");   // the user's, with a report file's name
  plant(dir + "/notes.txt", "mine\n");             // not a report name at all
  const std::vector<FolderEntry> report = {{"report.md", &kinds::report_file}, {"curves.csv", &kinds::report_file},
                                           {"contact.svg", &kinds::report_file}};
  OutputPlan plan;
  plan.folder("--report", dir, report);
  EXPECT_NE(problem(plan).find("curves.csv holds something that is not a surface report's file"), std::string::npos)
      << problem(plan);
  // an earlier report's file of ours not written again is removed; the user's files stay
  std::system(("rm '" + dir + "/curves.csv'").c_str());
  plant(dir + "/contact.svg",
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
        "width=\"10\"></svg>\n");
  OutputPlan again;
  again.folder("--report", dir, report);
  OutputTransaction outputs(again);
  outputs.stage(dir, "report.md", "# Surface report: x\n");
  EXPECT_EQ(outputs.commit(), std::vector<std::string>{dir + "/report.md"});
  EXPECT_EQ(entries(dir), (std::vector<std::string>{".asperity.lock", "notes.txt", "report.md"}));
  EXPECT_EQ(read_bytes(dir + "/notes.txt"), "mine\n");
}

TEST(OutputPolicy, NamesArePrintable) {
  EXPECT_EQ(asperity::printable_path("a\x1b[31mb\n"), "a\\x1B[31mb\\x0A");
}

// A command: the first SIGINT asks the run to stop (it unwinds, removing its temporaries), a
// second exits at once with 128 + SIGINT, removing the temporaries being written.
TEST(OutputPolicy, SignalsLeaveNoTemporary) {
  const std::string dir = test_directory("signal");
  for (int signals : {1, 2}) {
    const pid_t child = fork();
    if (child == 0) {
      asperity::install_output_signal_cleanup();
      try {
        OutputPlan plan;
        plan.file("--card", dir + "/card.inp", kinds::card);
        OutputTransaction outputs(plan);
        outputs.stage(dir + "/card.inp", card_text);
        for (int k = 0; k < signals; ++k) kill(getpid(), SIGINT);
        outputs.commit();
      } catch (const asperity::Interrupted&) {
        _exit(30);
      }
      _exit(1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), signals == 1 ? 30 : 128 + SIGINT);
    EXPECT_TRUE(entries(dir).empty()) << signals << " signals: " << (entries(dir).empty() ? "" : entries(dir)[0]);
  }
}

}  // namespace

// `--report out/` where out does not exist yet: the trailing separator names the folder (it was
// refused as "'out' is not a directory"), as does a relative path whose first folder is missing
// too (it read the status of a path that failed).
TEST(OutputPolicy, AFolderToMakeMayEndInASeparator) {
  const std::string dir = test_directory("folder-separator");
  for (const std::string& folder : {dir + "/out/", dir + "/new/deeper/"}) {
    OutputPlan plan(false);
    plan.folder("--report", folder, {{"report.md", &kinds::report_file}});
    EXPECT_NO_THROW(plan.check()) << folder;
  }
  const std::string here = std::filesystem::current_path().string();
  std::filesystem::current_path(dir);
  OutputPlan relative(false);
  relative.folder("--report", "first/second/", {{"report.md", &kinds::report_file}});
  EXPECT_NO_THROW(relative.check());
  std::filesystem::current_path(here);
}

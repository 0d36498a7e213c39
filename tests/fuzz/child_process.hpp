// SPDX-License-Identifier: Apache-2.0
// Runs a tool as a child process (argv as given, no shell) in a working
// directory with a time limit, and captures its exit status, stdout and stderr.
// Shared by the CLI tests and the fuzz driver.
#pragma once

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sgm::test {

struct ChildResult {
  int rc = -1;            // exit status, -1 when killed by a signal or timed out
  int signal = 0;         // the signal that ended it, if any
  bool timedOut = false;  // killed after the time limit
  std::string out, err;
};

inline std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::vector<std::string> textLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

// File names in dir (empty set when dir does not exist).
inline std::set<std::string> dirEntries(const std::string& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) names.insert(e.path().filename().string());
  return names;
}

// Runs program with args in cwd; stdout and stderr go to files in scratchDir
// (removed afterwards). Kills the child after timeoutSeconds.
inline ChildResult runChild(const std::string& program, const std::vector<std::string>& args, const std::string& cwd,
                            const std::string& scratchDir, double timeoutSeconds = 120) {
  const std::string outFile = scratchDir + "/child_stdout.txt", errFile = scratchDir + "/child_stderr.txt";
  std::vector<std::string> argvText = {program};
  argvText.insert(argvText.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argvText) argv.push_back(a.data());
  argv.push_back(nullptr);

  ChildResult r;
  const pid_t pid = ::fork();
  if (pid < 0) return r;
  if (pid == 0) {
    const int out = ::open(outFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::dup2(out, STDOUT_FILENO), ::dup2(err, STDERR_FILENO);
    ::close(out), ::close(err);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  int status = 0;
  for (auto pause = std::chrono::milliseconds(1);; pause = std::min(pause * 2, std::chrono::milliseconds(50))) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0) return r;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      r.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(pause);
  }
  if (WIFEXITED(status) && !r.timedOut) r.rc = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = readWholeFile(outFile);
  r.err = readWholeFile(errFile);
  std::remove(outFile.c_str());
  std::remove(errFile.c_str());
  return r;
}

// What is wrong with a run that should be a user error of tool: non-zero exit
// (not a signal, not a time-out), exactly one stderr line "TOOL: error: ..."
// containing needle, nothing on stdout. Empty when the run is such an error.
inline std::string userErrorProblem(const ChildResult& r, const std::string& tool, const std::string& needle = "") {
  if (r.timedOut) return "timed out (hang)";
  if (r.signal) return "killed by signal " + std::to_string(r.signal) + "; stderr: " + r.err;
  if (r.rc == 0) return "exit status 0; stdout: " + r.out;
  const std::vector<std::string> errLines = textLines(r.err);
  if (errLines.size() != 1) return std::to_string(errLines.size()) + " stderr lines, expected 1:\n" + r.err;
  if (r.err.back() != '\n') return "stderr line not terminated: " + r.err;
  if (errLines[0].rfind(tool + ": error: ", 0) != 0) return "stderr line without '" + tool + ": error: ': " + r.err;
  if (errLines[0].find(needle) == std::string::npos) return "'" + needle + "' not in: " + errLines[0];
  if (!r.out.empty()) return "stdout not empty: " + r.out;
  return "";
}

}  // namespace sgm::test

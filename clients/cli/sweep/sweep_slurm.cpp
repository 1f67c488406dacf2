// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/sweep_slurm.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "cli/sweep/sweep_local.hpp"

namespace wrc::cli {
namespace {

struct CommandResult {
  int status = -1;  // exit code, -1 when it did not exit normally
  std::string output;
};

// Runs argv (found on PATH) with stdout and stderr captured.
CommandResult run_command(const std::vector<std::string>& argv) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::vector<std::string> args = argv;
  std::vector<char*> c_args;
  for (std::string& a : args) c_args.push_back(a.data());
  c_args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::dup2(pipe_fds[1], 1);
    ::dup2(pipe_fds[1], 2);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    ::execvp(c_args[0], c_args.data());
    const std::string why = argv[0] + ": " + std::strerror(errno) + " (is Slurm's client, Debian's slurm-client, installed?)\n";
    (void)!::write(2, why.data(), why.size());
    _exit(127);
  }
  ::close(pipe_fds[1]);
  CommandResult r;
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(pipe_fds[0], buffer, sizeof buffer)) != 0) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    r.output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// text as one shell word.
std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '\r')) text.pop_back();
  return text;
}

}  // namespace

std::string submit_to_slurm(const SweepWork& work, const std::vector<std::size_t>& points,
                            const SlurmSubmission& submission) {
  if (points.empty()) throw std::logic_error("submit_to_slurm: no points");
  const std::string stamp = std::to_string(
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count());
  const std::string list = work.slurm_directory() + "/points-" + stamp + ".txt";
  const std::string script = work.slurm_directory() + "/job-" + stamp + ".sh";
  {
    std::ofstream out(list);
    for (std::size_t p : points) out << p << "\n";
    if (!out) throw std::runtime_error(list + ": cannot be written");
  }
  {
    std::ofstream out(script);
    out << "#!/bin/bash\n";
    out << "#SBATCH --job-name=wrc-sweep\n";
    out << "#SBATCH --array=0-" << points.size() - 1;
    if (submission.array_limit > 0) out << "%" << submission.array_limit;
    out << "\n#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
    out << "#SBATCH --output=" << work.logs_directory() << "/slurm-%A_%a.log\n";
    if (!submission.partition.empty()) out << "#SBATCH --partition=" << submission.partition << "\n";
    if (!submission.time.empty()) out << "#SBATCH --time=" << submission.time << "\n";
    out << "# Written by wrc sweep --slurm: task k runs line k+1 of the list (a grid point) with the same\n"
           "# program, which writes its row into the work directory (every node reaches both at these paths).\n";
    out << "set -eu\n";
    out << "point=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " << shell_quoted(list) << ")\n";
    out << "exec " << shell_quoted(own_executable());
    const std::string variable = "\"$point\"";
    for (const std::string& a : run_point_arguments(work, variable)) out << " " << (a == variable ? a : shell_quoted(a));
    out << "\n";
    if (!out) throw std::runtime_error(script + ": cannot be written");
  }
  std::vector<std::string> argv{"sbatch", "--parsable"};
  for (const std::string& a : submission.sbatch_args) argv.push_back(a);
  argv.push_back(script);
  const CommandResult r = run_command(argv);
  const std::string output = trimmed(r.output);
  if (r.status != 0) throw std::runtime_error("sbatch failed (exit " + std::to_string(r.status) + "): " + output);
  // --parsable: "jobid" or "jobid;cluster" on the last line.
  std::string job = output.substr(output.rfind('\n') == std::string::npos ? 0 : output.rfind('\n') + 1);
  job = job.substr(0, job.find(';'));
  if (job.empty() || job.find_first_not_of("0123456789") != std::string::npos)
    throw std::runtime_error("sbatch answered no job id: " + output);
  return job;
}

bool slurm_job_active(const std::string& job) {
  const CommandResult r = run_command({"squeue", "--noheader", "--jobs", job, "--format=%i %T"});
  if (r.status == 0) return !trimmed(r.output).empty();
  if (r.output.find("Invalid job id") != std::string::npos) return false;
  throw std::runtime_error("squeue failed (exit " + std::to_string(r.status) + "): " + trimmed(r.output));
}

}  // namespace wrc::cli

#!/usr/bin/python3
"""The docs' examples, run as written (issue 39, item 5): README.md and docs/*.md.

    /usr/bin/python3 tests/docs_examples.py [--build BUILD_DIR] [--list] [FILE.md ...]

ctest runs it as `docs_examples` (label `docs`). It extracts the fenced code blocks of README.md and
docs/*.md, runs those meant to be run and fails naming the file, the line of the block (and of the
failing command or Python line) and the error. A block is named by the line of its opening
fence, a command or a traceback's line by its own line in the .md file.

What runs
  ```sh / ```bash blocks: the block's text is one bash script (`set -eo pipefail`), as written, but
    for the commands skipped below (each replaced by `:` so that the line numbers stay the doc's);
    a failing command is named by its line in the .md file.
  ```python blocks: each block is written to a script of its own, padded with blank lines so that
    its line numbers are the .md file's, and run by this interpreter (/usr/bin/python3), as a reader
    who saves the block and runs it would: one interpreter per block, no state shared between blocks
    (no block of the docs builds on another; an example's main guard, as asperity.batch needs, works
    as in a user's script).
  Both with cwd = a fresh temporary directory holding symbolic links `build` -> the build directory,
  and `tests`, `tables`, `examples` -> the source tree's (read-only inputs the examples name), with
  PYTHONPATH=<build>/python, HOME and MPLCONFIGDIR in the temporary directory. So `build/asperity`,
  `tests/data/...` and `tables/scenes/...` resolve as from the repository root, and every file an
  example writes (ke.h5, contact.svg, results/, out/, ...) lands in the temporary directory: nothing
  is written into the source tree (no example writes into the linked folders).

What does not run
  - Blocks of any other language or none (C, C++, Fortran, TOML, text output, diagrams): fragments
    or output, on purpose.
  - A block preceded by `<!-- docs-examples: skip (reason) -->`: reported with its reason.
  - In sh blocks, these commands (reported with the reason, the rest of the block runs):
      `bash scripts/setup.sh`     installs packages with apt-get and rebuilds: the build exists
                                  (`bash scripts/setup.sh && X` runs X);
      apt-get, pip install, python -m venv, `python3 -m pip`: change the system or need an index;
      cmake (configure, --build, --install), cc, gfortran: compile or install for minutes, or
                                  need an install prefix (P);
      pkg-config                  needs asperity installed (the cmake --install above, skipped);
      ctest                       the whole suite, this test among it;
      build-fuzz/..., build/bench/..., bench/..., scripts/bench-*.sh: fuzzing (10 min) and benchmarks (timing runs);
      topography/scripts/...      regenerates the docs' figures into the source tree;
      a command with a placeholder (FILE, MAP, DIR, INPUT.csv, CORPUS_COPY, MAIN/, a lone P or P/)
      or a synopsis (`[--option ...]`): not a command as written.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LINKED = ("tests", "tables", "examples")  # read-only inputs the examples name, linked into the work dir
RUN_LANGUAGES = {"sh": "sh", "bash": "sh", "shell": "sh", "python": "python", "py": "python"}
SKIP_MARKER = re.compile(r"^\s*<!--\s*docs-examples:\s*skip\s*(?:\((.*)\))?\s*-->\s*$")
FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})\s*([\w+-]*)")
TIMEOUT = 120  # s, one block

# (pattern on the command, reason): the first that matches skips the command
SKIPPED_COMMANDS = [
    (r"^(sudo\s+)?apt(-get)?\b", "apt-get: installs system packages"),
    (r"(^|\s)(\S*python3?|\S*/pip3?|pip3?)\s+(-m\s+)?(pip\s+)?install\b|\s-m\s+pip\b|\s-m\s+venv\b",
     "pip/venv: installs packages or builds the module again"),
    (r"^(bash\s+)?scripts/setup\.sh\b", "scripts/setup.sh: installs packages and rebuilds (the build exists)"),
    (r"^ctest\b", "ctest: the whole test suite, this test among it"),
    (r"^cmake\b", "cmake: configures, builds or installs (minutes, or an install prefix)"),
    (r"^(cc|gcc|g\+\+|c\+\+|gfortran)\b", "a compiler: needs an installed prefix"),
    (r"pkg-config\b", "pkg-config: needs asperity installed (cmake --install, skipped)"),
    (r"^build-fuzz/", "fuzzing: ten minutes a target"),
    (r"^(build/)?bench/|^\S*python3?\s+bench/", "a benchmark: timing runs, minutes"),
    (r"^([A-Z_]+=\S*\s+)*(bash\s+)?scripts/bench-[\w-]+\.sh\b", "a benchmark: timing runs against other builds, minutes"),
    (r"^(bash\s+)?topography/scripts/", "regenerates the docs' figures into the source tree"),
    (r"\[--", "a synopsis, not a command"),
    (r"(^|[\s/=])(FILE|MAP|DIR|INPUT\.csv|CORPUS_COPY|MAIN/\S*|P/\S*|P)(?=$|[\s,/;)])",
     "a placeholder (FILE, MAP, DIR, P, ...): not a command as written"),
]


def blocks_of(path):
    """(language, first line of code (1-based), code lines, skip reason or None) of each fenced block."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    found, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, language = m.group(1), m.group(2), m.group(3).lower()
        j = i + 1
        while j < len(lines) and not re.match(r"^\s*" + re.escape(fence[0]) + "{%d,}\\s*$" % len(fence), lines[j]):
            j += 1
        code = [line[len(indent):] if line.startswith(indent) else line for line in lines[i + 1:j]]
        k = i - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        marker = SKIP_MARKER.match(lines[k]) if k >= 0 else None
        skip = (marker.group(1) or "no reason given") if marker else None
        found.append((language, i + 2, code, skip))
        i = j + 1
    return found


def without_comment(text):
    """text without a trailing `# comment` (a # after a blank, outside single quotes)."""
    quoted = False
    for k, c in enumerate(text):
        if c == "'":
            quoted = not quoted
        elif c == "#" and not quoted and (k == 0 or text[k - 1].isspace()):
            return text[:k]
    return text


def commands_of(code):
    """(first index, last index, text) of each command of a shell block: continuation lines and
    quotes spanning lines joined; comments and blank lines are not commands."""
    commands, i = [], 0
    while i < len(code):
        start, text = i, code[i]
        while True:
            bare = without_comment(text)
            if bare.rstrip().endswith("\\") and i + 1 < len(code):
                i += 1
                text = bare.rstrip()[:-1] + " " + code[i].strip()
            elif bare.count("'") % 2 == 1 and i + 1 < len(code):
                i += 1
                text = text + "\n" + code[i]
            else:
                break
        stripped = text.strip()
        if stripped and not stripped.startswith("#"):
            commands.append((start, i, stripped))
        i += 1
    return commands


def skip_reason(command):
    line = without_comment(command).strip()
    line = re.sub(r"^export\s+\w+=", "", line)
    for pattern, reason in SKIPPED_COMMANDS:
        if re.search(pattern, line):
            return reason
    return None


class Runner:
    def __init__(self, build, work):
        self.build, self.work = build, work
        self.env = dict(os.environ)
        python = os.path.join(build, "python")
        self.env["PYTHONPATH"] = python + (os.pathsep + self.env["PYTHONPATH"] if self.env.get("PYTHONPATH") else "")
        self.env["HOME"] = work
        self.env["MPLCONFIGDIR"] = os.path.join(work, ".matplotlib")
        self.env["MPLBACKEND"] = "Agg"
        self.env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + self.env.get("PATH", "")
        self.failures, self.skipped, self.ran = [], [], []

    def fresh_dir(self, name):
        cwd = os.path.join(self.work, name)
        os.makedirs(cwd)
        os.symlink(self.build, os.path.join(cwd, "build"))
        for entry in LINKED:
            os.symlink(os.path.join(SOURCE, entry), os.path.join(cwd, entry))
        return cwd

    def execute(self, argv, cwd):
        started = time.perf_counter()
        try:
            done = subprocess.run(argv, cwd=cwd, env=self.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  text=True, timeout=TIMEOUT, stdin=subprocess.DEVNULL)
            return done.returncode, done.stdout, done.stderr, time.perf_counter() - started
        except subprocess.TimeoutExpired as e:
            out = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
            err = e.stderr.decode(errors="replace") if isinstance(e.stderr, bytes) else (e.stderr or "")
            return None, out, err + f"\ntimed out after {TIMEOUT} s", time.perf_counter() - started

    def run_sh(self, where, name, first, code):
        script = list(code)
        for start, end, command in commands_of(code):
            reason = skip_reason(command)
            if reason is None and command.startswith("bash scripts/setup.sh && "):
                rest = command[len("bash scripts/setup.sh && "):]
                self.skipped.append((f"{where}:{first + start}", "bash scripts/setup.sh", skip_reason("bash scripts/setup.sh")))
                reason = skip_reason(rest)
                if reason is None:
                    script[start] = script[start].replace("bash scripts/setup.sh && ", "", 1)
                    continue
            if reason is not None:
                self.skipped.append((f"{where}:{first + start}", command.split("\n")[0][:90], reason))
                for k in range(start, end + 1):
                    script[k] = ":"
        if all(line.strip() in ("", ":") or line.strip().startswith("#") for line in script):
            return
        # line 1 of the script is the preamble: doc line = first + LINENO - 2
        text = ("set -eo pipefail; trap 'echo \"docs-examples: the command at line $((LINENO + %d)) failed "
                "(exit $?)\" >&2' ERR\n" % (first - 2)) + "\n".join(script) + "\n"
        status, out, err, seconds = self.execute(["bash", "-c", text, "docs-example"], self.fresh_dir(name))
        self.report(where, first, "sh", status, out, err, seconds)

    def run_python(self, where, name, first, code):
        cwd = self.fresh_dir(name)
        script = os.path.join(cwd, name + ".py")
        with open(script, "w", encoding="utf-8") as f:
            f.write("\n" * (first - 1) + "\n".join(code) + "\n")
        status, out, err, seconds = self.execute([sys.executable, script], cwd)
        err = err.replace(script, where)
        self.report(where, first, "python", status, out, err, seconds)

    def report(self, where, first, language, status, out, err, seconds):
        label = f"{where}:{first - 1}"  # the opening fence
        self.ran.append((label, language, seconds, status == 0))
        if status == 0:
            print(f"ok      {label} ({language}, {seconds:.1f} s)", flush=True)
            return
        tail = "\n".join((err.strip() or out.strip()).splitlines()[-15:])
        self.failures.append((label, language, tail))
        print(f"FAILED  {label} ({language}, {seconds:.1f} s, "
              f"{'timed out' if status is None else 'exit ' + str(status)})\n"
              + "\n".join("        " + line for line in tail.splitlines()), flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(SOURCE, "build"), help="the CMake build directory")
    parser.add_argument("--list", action="store_true", help="list the blocks and what is done with each")
    parser.add_argument("files", nargs="*", help=".md files (default: README.md and docs/*.md)")
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    files = args.files or ["README.md"] + sorted(
        os.path.join("docs", f) for f in os.listdir(os.path.join(SOURCE, "docs")) if f.endswith(".md"))
    if not os.path.isfile(os.path.join(build, "asperity")) or not os.path.isdir(os.path.join(build, "python")):
        print(f"docs_examples: {build} has no asperity command or python/ folder: build it first", file=sys.stderr)
        return 2
    started = time.perf_counter()
    work = tempfile.mkdtemp(prefix="asperity-docs-examples-")
    runner = Runner(build, work)
    try:
        for relative in files:
            path = relative if os.path.isabs(relative) else os.path.join(SOURCE, relative)
            where = os.path.relpath(path, SOURCE)
            for language, first, code, skip in blocks_of(path):
                kind = RUN_LANGUAGES.get(language)
                if kind is None:
                    continue
                if skip is not None:
                    runner.skipped.append((f"{where}:{first - 1}", f"the {language} block", skip))
                    continue
                if args.list:
                    print(f"{where}:{first} {kind}")
                    continue
                name = re.sub(r"[^\w]+", "_", where) + f"_{first}"
                (runner.run_sh if kind == "sh" else runner.run_python)(where, name, first, code)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for label, what, reason in runner.skipped:
        print(f"skipped {label}: {what}: {reason}")
    seconds = time.perf_counter() - started
    print(f"docs_examples: {len(runner.ran)} blocks run, {len(runner.failures)} failed, "
          f"{len(runner.skipped)} skipped, {seconds:.1f} s")
    for label, language, tail in runner.failures:
        first_line = tail.splitlines()[-1] if tail else "(no output)"
        print(f"docs_examples: FAILED {label} ({language}): {first_line}", file=sys.stderr)
    return 1 if runner.failures else 0


if __name__ == "__main__":
    sys.exit(main())

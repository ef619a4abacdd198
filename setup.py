"""asperity is built by pip with its own backend (pyproject.toml, python/packaging/asperity_build.py),
not by setup.py: `python3 -m pip install .` (see the README's section Python)."""
import sys

if __name__ == "__main__":
    sys.exit(f"asperity: build it with `{sys.executable} -m pip install .` (pyproject.toml's backend, "
             f"python/packaging/asperity_build.py); `{sys.executable} python/packaging/asperity_build.py` "
             "says what this interpreter lacks")

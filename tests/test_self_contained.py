"""The repository depends on nothing outside it: no text file names a path of some machine.

Reference data the tests and the vessel scripts read live in the repository
(vessels/<vessel>/source/, with their provenance and licence); a path to a folder beside the
checkout or to a user's home would make a fresh clone fail or skip tests.
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SKIP_DIRS = {".git", ".venv", "venv", "__pycache__", ".pytest_cache", ".ruff_cache", "build",
             "dist", "results", ".ipynb_checkpoints"}
TEXT_SUFFIXES = {".py", ".md", ".yaml", ".yml", ".toml", ".txt", ".ipynb", ".csv", ".cfg", ".ini",
                 ".rst", ".json", ".html", ""}
# written in pieces so that this file does not match itself
MACHINE_PATH = re.compile("|".join([
    r"/wo" r"rk/",                      # the development sandbox
    r"\.\./sha" r"red\b",               # a folder beside the checkout
    r"/ho" r"me/[A-Za-z0-9_.-]+/",      # a Unix home
    r"/Us" r"ers/[A-Za-z0-9_.-]+/",     # a macOS home
    r"[A-Za-z]:\\\\Us" r"ers\\\\",      # a Windows home (JSON- or Python-escaped)
]))


def _text_files():
    for path in ROOT.rglob("*"):
        rel = path.relative_to(ROOT)
        if any(part in SKIP_DIRS or part.endswith(".egg-info") for part in rel.parts):
            continue
        if path.is_file() and path.suffix in TEXT_SUFFIXES and path.stat().st_size < 20_000_000:
            yield path, rel


def test_no_machine_paths_in_the_repository():
    hits = []
    for path, rel in _text_files():
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        for n, line in enumerate(text.splitlines(), 1):
            m = MACHINE_PATH.search(line)
            if m:
                hits.append(f"{rel}:{n}: {m.group(0)}")
    assert not hits, "machine paths in the repository:\n" + "\n".join(hits[:50])


def test_reference_files_are_in_the_repository():
    # the files tests/hydro, tests/post, tests/test_frequency_domain_api.py and the
    # make_database.py scripts read; each source folder states provenance and licence
    for rel in ["vessels/oc3_hywind/source/Spar.1", "vessels/oc3_hywind/source/Spar.3",
                "vessels/oc3_hywind/source/Spar.hst", "vessels/oc4_semi/source/marin_semi.1",
                "vessels/oc4_semi/source/marin_semi.hst", "vessels/oc4_semi/source/marin_semi.12d",
                "vessels/oc4_semi/source/RAFT_OC4semi.yaml",
                "vessels/floatel_like/source/floatel_superior.yaml"]:
        assert (ROOT / rel).is_file(), rel
    for vessel in ("oc3_hywind", "oc4_semi"):
        notice = (ROOT / "vessels" / vessel / "source" / "README.md").read_text(encoding="utf-8")
        assert "Apache" in notice and "github.com/OpenFAST/r-test" in notice
    assert "Apache License" in (ROOT / "docs" / "licences" / "LICENSE-APACHE-2.0").read_text()

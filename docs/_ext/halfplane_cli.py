"""Sphinx directive ``halfplane-cli``: the command-line reference, read from the command's own
``--help`` when the site is built, so it cannot drift from the command. Every command that
``halfplane --help`` lists gets a section with its help text, and every figure of ``halfplane
plot`` one below it.

The command is ``$HALFPLANE_CLI``, else target/debug/halfplane (``./scripts/docs`` builds it)."""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path
from typing import Any

from docutils import nodes
from docutils.statemachine import StringList
from sphinx.application import Sphinx
from sphinx.errors import ExtensionError
from sphinx.util.docutils import SphinxDirective
from sphinx.util.nodes import nested_parse_with_titles

ROOT = Path(__file__).resolve().parents[2]


def command() -> Path:
    given = os.environ.get("HALFPLANE_CLI")
    path = Path(given) if given else ROOT / "target" / "debug" / "halfplane"
    if not path.is_file():
        raise ExtensionError(
            f"the halfplane command is not at {path}: build it (cargo build -p halfplane-cli) or "
            "set HALFPLANE_CLI"
        )
    return path


def help_text(args: list[str]) -> str:
    done = subprocess.run(
        [str(command()), *args, "--help"],
        capture_output=True,
        text=True,
        check=False,
        env={**os.environ, "COLUMNS": "86"},  # the width of furo's code blocks
    )
    if done.returncode != 0:
        raise ExtensionError(f"halfplane {' '.join(args)} --help failed: {done.stderr}")
    return done.stdout.rstrip()


def listed(text: str, heading: str) -> list[str]:
    """The names under ``heading`` ("Commands:", "Figures:") of a clap help text, without help."""
    names: list[str] = []
    inside = False
    for line in text.splitlines():
        if line.strip() == heading:
            inside = True
        elif inside and not line.startswith(" "):
            break
        elif inside:
            match = re.match(r"^  ([a-z][a-z0-9-]*)\s{2,}", line)
            if match and match.group(1) != "help":
                names.append(match.group(1))
    if not names:
        raise ExtensionError(f"no {heading} found in the help text:\n{text}")
    return names


def section(title: str, underline: str, text: str) -> list[str]:
    heading = f"``{title}``"
    body = ["", heading, underline * len(heading), "", ".. code-block:: text", ""]
    return body + ["   " + line if line else "" for line in text.splitlines()] + [""]


class CliReference(SphinxDirective):
    """Sections for ``halfplane --help`` and each command's (and plot figure's) help."""

    has_content = False

    def run(self) -> list[nodes.Node]:
        top = help_text([])
        lines = ["", ".. code-block:: text", ""] + ["   " + ln if ln else "" for ln in top.splitlines()]
        for name in listed(top, "Commands:"):
            text = help_text([name])
            lines += section(f"halfplane {name}", "-", text)
            if name == "plot":
                for figure in listed(text, "Figures:"):
                    lines += section(f"halfplane plot {figure}", "~", help_text(["plot", figure]))
        container = nodes.container()
        nested_parse_with_titles(self.state, StringList(lines, source="halfplane --help"), container)
        return list(container.children)


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("halfplane-cli", CliReference)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}

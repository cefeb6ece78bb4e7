# Runs every ```python block of a Markdown file in order, in one namespace, the way a reader would
# paste them into one session, with the working directory holding trapdem-out/demo (a link to the
# run folder the test fixture made). Fails on the first block that raises, naming it, and when a
# figure the blocks save is missing or not a PNG. Usage: python3 python_docs_test.py DOC.md RUN_DIR
# [--without-the-module]: then only the blocks after the heading "# Reading the files without the
# module" (a build without the Python module: they need h5py, pandas and matplotlib only).
import os
import re
import sys
import tempfile
import traceback

doc, run = sys.argv[1], os.path.abspath(sys.argv[2])
text = open(doc, encoding="utf-8").read()
first_line = 1  # of text in the document, for the blocks' line numbers
if sys.argv[3:] == ["--without-the-module"]:
    heading = "\n# Reading the files without the module\n"
    if heading not in text:
        sys.exit(f"{doc}: no heading '{heading.strip()}'")
    first_line += text[: text.index(heading)].count("\n") + 1
    text = text[text.index(heading) + 1:]
elif sys.argv[3:]:
    sys.exit("usage: python_docs_test.py DOC.md RUN_DIR [--without-the-module]")
blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
if len(blocks) < 5:
    sys.exit(f"{doc}: only {len(blocks)} python blocks found; the pattern or the document changed")

with tempfile.TemporaryDirectory(prefix="trapdem-python-docs-") as work:
    os.makedirs(os.path.join(work, "trapdem-out"))
    os.symlink(run, os.path.join(work, "trapdem-out", "demo"))
    os.chdir(work)
    namespace = {"__name__": "__main__"}
    for k, block in enumerate(blocks, 1):
        line = first_line + text[: text.index(block)].count("\n")
        print(f"--- block {k} ({doc}:{line})")
        try:
            exec(compile(block, f"{doc}:block{k}", "exec"), namespace)
        except Exception:
            traceback.print_exc()
            sys.exit(f"{doc}:{line}: block {k} failed")
    figures = re.findall(r"savefig\(\"([^\"]+)\"", "".join(blocks))
    if not figures:
        sys.exit(f"{doc}: no figure saved (savefig) in its blocks")
    for name in figures:
        with open(name, "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                sys.exit(f"{name}: not a PNG")
        print(f"{name}: {os.path.getsize(name)} bytes")
print(f"{len(blocks)} blocks of {doc} ran")

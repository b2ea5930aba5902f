#!/usr/bin/env python3
"""Makes the built page one HTML file that runs from the disk, with no server (as PhET's offline
files do): web/build.sh --single-file calls it on the folder it built.

    single_file.py BUILT_FOLDER OUT.html

A page opened from file:// may not import a module or fetch a file beside it, so everything is
inline: wasm-bindgen's JavaScript glue in the page's module script, the module's bytes in Base64,
and the worker's script (the same glue and web/worker.js) in a blob the page names in
window.INERTIA_LAB_WORKER (crates/app/src/platform/web.rs starts the worker from there). Chromium
refuses a module worker from a blob made by a page opened from the disk (its origin is opaque),
so the worker's copy of the glue is made a classic script: no export, no import.meta.
"""

import base64
import json
import re
import sys
from pathlib import Path

GLUE = "inertia_lab_web.js"
MODULE = "inertia_lab_web_bg.wasm"
# The module script of web/index.html, which imports the glue from beside the page.
BOOT = re.compile(r'<script type="module">\s*import init from "\./inertia_lab_web\.js";(.*?)</script>', re.S)
WORKER_IMPORT = re.compile(r'^import init, \{ run_job \} from "\./inertia_lab_web\.js";$', re.M)
# What makes the glue a module: its export statements, and import.meta (only where no module
# is given to init, which the worker always is).
EXPORT_LIST = re.compile(r"^export \{[^}]*\};?$", re.M)
EXPORTED = re.compile(r"^export (function|class|const|let) ", re.M)


def classic(glue: str) -> str:
    """The glue as a classic script's code: the same functions, nothing exported."""
    if EXPORT_LIST.search(glue) is None:
        sys.exit(f"single_file.py: {GLUE} has no export list: wasm-bindgen's output changed")
    script = EXPORTED.sub(r"\1 ", EXPORT_LIST.sub("", glue))
    script = script.replace("import.meta.url", "self.location.href")
    if re.search(r"^\s*(export|import)\b", script, re.M):
        sys.exit(f"single_file.py: {GLUE} still has an import or export a classic script cannot hold")
    return script


def main(built: Path, out: Path) -> None:
    page = (built / "index.html").read_text()
    glue = (built / GLUE).read_text()
    worker = (built / "worker.js").read_text()
    wasm = base64.b64encode((built / MODULE).read_bytes()).decode("ascii")
    boot = BOOT.search(page)
    if boot is None:
        sys.exit(f"single_file.py: {built / 'index.html'} has no module script importing {GLUE}")
    if WORKER_IMPORT.search(worker) is None:
        sys.exit(f"single_file.py: {built / 'worker.js'} does not import init and run_job from {GLUE}")
    # The glue's default export is its init function; both scripts call it `init`.
    inline_glue = f"{glue}\nconst init = __wbg_init;\n"
    worker_code = f"{classic(glue)}\nconst init = __wbg_init;\n" + WORKER_IMPORT.sub("", worker)
    script = (
        '<script type="module">\n'
        f"{inline_glue}"
        f"window.INERTIA_LAB_WORKER = URL.createObjectURL(new Blob([{json.dumps(worker_code)}], "
        '{ type: "text/javascript" }));\n'
        f'const MODULE = Uint8Array.from(atob("{wasm}"), (c) => c.charCodeAt(0));\n'
        # init() with the module's bytes instead of fetching the file beside the page.
        + boot.group(1).replace("init()", "init({ module_or_path: MODULE })", 1)
        + "</script>"
    )
    if "init({ module_or_path: MODULE })" not in script:
        sys.exit("single_file.py: the page's module script no longer calls init()")
    out.parent.mkdir(parents=True, exist_ok=True)
    # A function as the replacement: the script's backslashes are its own, not re's escapes.
    out.write_text(BOOT.sub(lambda _: script, page, count=1))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: single_file.py BUILT_FOLDER OUT.html")
    main(Path(sys.argv[1]), Path(sys.argv[2]))

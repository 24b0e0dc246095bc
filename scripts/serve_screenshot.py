#!/usr/bin/env python3
"""The picture of `ris serve` in docs/serve.md (docs/images/serve-page.png):
`ris serve` on its defaults (the standard scene, the figure-4-5 radar), the
page loaded in the headless Chromium of the browser test
(tests/serve/serve_browser.py: its driver, a 1600 x 1000 window) and
screenshot once the first image is drawn.

Exit 77 with a message when Chromium, chromedriver or Selenium is missing
(scripts/install-deps.sh installs them).

Usage: scripts/serve_screenshot.py RIS_EXE OUT.png
"""
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "serve"))
from serve_browser import SKIP, find_chromium, image_run, make_driver  # noqa: E402
from serve_harness import Server, wait_until  # noqa: E402


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    ris_exe, out_png = sys.argv[1], sys.argv[2]
    try:
        import selenium  # noqa: F401 (only whether it is there)
    except ImportError:
        print("SKIP: python3-selenium not installed (scripts/install-deps.sh)")
        return SKIP
    import shutil
    if not find_chromium() or not shutil.which("chromedriver"):
        print("SKIP: chromium and chromedriver not found (scripts/install-deps.sh)")
        return SKIP
    with tempfile.TemporaryDirectory(prefix="ris-serve-shot-") as work:
        server = Server(ris_exe, os.path.join(work, "out"))
        driver = None
        try:
            driver = make_driver(os.path.join(work, "profile"))
            driver.get(server.url + "/")
            wait_until(lambda: image_run(driver), 60, "the first image")
            driver.save_screenshot(out_png)
        finally:
            if driver is not None:
                driver.quit()
            server.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""End-to-end test of `ris serve` in a real headless browser (Debian's
chromium + chromium-driver, python3-selenium): load the page on the standard
scene, move the depression slider and wait until the image changes, click a
pixel and read the inspector, add a box and see its shadow appear, save the
scene and read it back with `ris scene info`. Screenshots go to OUT_DIR as
artefacts.

Exit 77 (ctest: skipped) with a message when Chromium or Selenium is missing.

Usage: serve_browser.py RIS_EXE OUT_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_harness import Server, wait_until  # noqa: E402

SKIP = 77


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def make_driver(profile_dir):
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service
    opts = Options()
    opts.binary_location = find_chromium()
    # As root in a container: no sandbox; and nothing that reaches the network.
    for arg in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking",
                "--disable-component-update", "--disable-sync",
                "--disable-dev-shm-usage", f"--user-data-dir={profile_dir}",
                "--window-size=1600,1000"):
        opts.add_argument(arg)
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=opts)


def inspector(driver):
    """The inspector's rows as {label: text}, read in one script (the page
    replaces the table as answers arrive)."""
    return driver.execute_script(
        "const out = {};"
        "for (const tr of document.querySelectorAll('#inspector tr')) {"
        "  const td = tr.querySelectorAll('td');"
        "  if (td.length === 2) out[td[0].textContent] = td[1].textContent;"
        "}"
        "return out;")


def click_pixel(driver, img_id, col, row):
    """Clicks the centre of pixel (col, row) of an <img> as shown (zoomed)."""
    from selenium.webdriver.common.action_chains import ActionChains
    img = driver.find_element("id", img_id)
    w, h, nw, nh = driver.execute_script(
        "const i = arguments[0]; const r = i.getBoundingClientRect();"
        "return [r.width, r.height, i.naturalWidth, i.naturalHeight];", img)
    # Selenium 4 offsets are from the element's centre.
    dx = (col + 0.5) / nw * w - w / 2
    dy = (row + 0.5) / nh * h - h / 2
    ActionChains(driver).move_to_element_with_offset(img, int(round(dx)), int(round(dy))) \
        .click().perform()


def image_run(driver):
    return driver.execute_script(
        "const i = document.getElementById('image');"
        "return i.complete && i.naturalWidth > 0 ? i.dataset.run || '' : '';")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    ris_exe, out_dir = sys.argv[1], sys.argv[2]
    if not find_chromium() or not shutil.which("chromedriver"):
        print("SKIP: chromium and chromedriver not found (scripts/install-deps.sh installs "
              "chromium, chromium-driver and python3-selenium)")
        return SKIP
    try:
        import selenium  # noqa: F401
    except ImportError:
        print("SKIP: python3-selenium not installed (scripts/install-deps.sh)")
        return SKIP
    os.makedirs(out_dir, exist_ok=True)
    work = tempfile.mkdtemp(prefix="ris-serve-e2e-")
    server = Server(ris_exe, os.path.join(work, "out"))
    driver = None
    try:
        driver = make_driver(os.path.join(work, "profile"))
        driver.get(server.url + "/")
        first = wait_until(lambda: image_run(driver), 60, "the first image")
        driver.save_screenshot(os.path.join(out_dir, "1-loaded.png"))

        # The depression slider, moved with the keyboard as a person would.
        from selenium.webdriver.common.keys import Keys
        slider = driver.find_element("id", "depression")
        before = slider.get_attribute("value")
        for _ in range(4):
            slider.send_keys(Keys.ARROW_RIGHT)
        assert slider.get_attribute("value") != before, "the slider did not move"
        second = wait_until(lambda: (r := image_run(driver)) and r != first and r, 60,
                            "the image after moving the slider")
        print(f"depression {before} -> {slider.get_attribute('value')} deg: "
              f"image run {first} -> {second}")
        driver.save_screenshot(os.path.join(out_dir, "2-depression.png"))

        # A pixel of the slant image, then the inspector.
        click_pixel(driver, "image", 120, 350)
        rows = wait_until(lambda: (i := inspector(driver)) and "slant range, m" in i and i, 30,
                          "the inspector")
        print(f"inspector: slant range {rows['slant range, m']} m, greytone {rows['greytone']}")
        # Shown at about one screen pixel per image pixel: within one of the aim.
        assert abs(int(rows["bin"]) - 120) <= 1 and abs(int(rows["line"]) - 350) <= 1, rows

        # A box at the scene's centre (Add box), then its shadow: east of it,
        # as the radar looks east. Check the cell before and after.
        driver.find_element("css selector", ".overlay[value=shadow]").click()
        col, row = 560, 325  # 1200 ft east of the box, before the hemisphere

        def scene_cell_clicked():
            # The scene is shown at under one screen pixel per cell: a click
            # lands within a cell or two of the one aimed at.
            i = inspector(driver)
            ok = "col" in i and abs(int(i["col"]) - col) <= 2 and abs(int(i["row"]) - row) <= 2
            return ok and i

        click_pixel(driver, "scene", col, row)
        cell = wait_until(scene_cell_clicked, 30, "the scene inspector")
        flags_before = cell["flags"]
        run_before = image_run(driver)
        driver.find_element("id", "add-box").click()
        wait_until(lambda: (r := image_run(driver)) and r != run_before, 60,
                   "the image after adding a box")
        driver.execute_script("document.getElementById('inspector').innerHTML = '';")
        click_pixel(driver, "scene", col, row)
        cell_after = wait_until(scene_cell_clicked, 30, "the scene inspector")
        assert (cell_after["row"], cell_after["col"]) == (cell["row"], cell["col"])
        flags_after = cell_after["flags"]
        print(f"cell (row {cell['row']}, col {cell['col']}): flags '{flags_before}' -> "
              f"'{flags_after}'")
        assert "shadow" not in flags_before, flags_before
        assert "shadow" in flags_after, flags_after
        driver.save_screenshot(os.path.join(out_dir, "3-box-shadow.png"))

        # Save the scene and read it back with the command line.
        name = driver.find_element("id", "save-name")
        name.clear()
        name.send_keys("e2e-scene")
        driver.find_element("id", "save-scene").click()
        saved = wait_until(lambda: (t := driver.find_element("id", "saved").text)
                           .startswith("saved ") and t, 30, "the saved scene")
        # Answers name files relative to --out, never by absolute paths.
        path = os.path.join(work, "out", saved.split()[1])
        info = subprocess.run([ris_exe, "scene", "info", path], capture_output=True, text=True)
        print(info.stdout.strip().splitlines()[0] if info.stdout else info.stderr)
        assert info.returncode == 0, info.stderr
        assert "box" in open(path).read()
        driver.save_screenshot(os.path.join(out_dir, "4-saved.png"))
        errors = driver.find_element("id", "error").text
        assert errors == "", f"the page shows an error: {errors}"
    finally:
        if driver is not None:
            driver.quit()
        code, out = server.stop()
        shutil.rmtree(work, ignore_errors=True)
    assert code == 0, f"ris serve exit code {code} after SIGINT:\n{out}"
    print(f"ok; screenshots in {out_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

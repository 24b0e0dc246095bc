#!/usr/bin/env python3
"""End-to-end test of `ris serve` in a real headless browser (Debian's
chromium + chromium-driver, python3-selenium): load the page on the standard
scene, move the depression slider and wait until the image changes, click a
pixel and read the inspector, follow the linked cursor into the scene and
back, check the scale bar against the cell size and the legend against the
scene picture's colours, switch every overlay on and off (nothing drawn when
off) and through the presentations (no stale overlay), add a box and see its
shadow appear (written in the scene's feet), save the scene and read it back
with `ris scene info`, upload a DEM and simulate it (latitude in the
inspector within the DEM), zoom the slant view with the scene and back
(linked through the geocoding), compare two runs in two bands (side by side,
swipe, and the difference view's value against the inspector's), and load the page without Leaflet and Chart.js
(plain images and a note). Screenshots go to OUT_DIR as artefacts.

Exit 77 (ctest: skipped) with a message when Chromium or Selenium is missing.

Usage: serve_browser.py RIS_EXE OUT_DIR
"""
import os
import re
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


def shown(driver, element_id):
    """True when the element takes space on screen (not display: none)."""
    return driver.execute_script(
        "const e = document.getElementById(arguments[0]);"
        "return !!e && getComputedStyle(e).display !== 'none' && e.getClientRects().length > 0;",
        element_id)


def aim_tolerance(driver, img_id):
    """Image pixels per screen pixel along x and y (a click lands within one
    screen pixel of its aim)."""
    return driver.execute_script(
        "const i = document.getElementById(arguments[0]); const r = i.getBoundingClientRect();"
        "return [Math.max(1, Math.ceil(i.naturalWidth / r.width)),"
        "        Math.max(1, Math.ceil(i.naturalHeight / r.height))];", img_id)


def cursor(driver, cursor_id, img_id):
    """The linked cursor's cell (data-col, data-row) and the image cell under
    its drawn centre, or None when it is hidden."""
    return driver.execute_script(
        "const c = document.getElementById(arguments[0]), i = document.getElementById(arguments[1]);"
        "if (c.hidden) return null;"
        "const r = c.getBoundingClientRect(), q = i.getBoundingClientRect();"
        "const x = (r.left + r.width / 2 - q.left) / q.width * i.naturalWidth;"
        "const y = (r.top + r.height / 2 - q.top) / q.height * i.naturalHeight;"
        "return [Number(c.dataset.col), Number(c.dataset.row), Math.floor(x), Math.floor(y)];",
        cursor_id, img_id)


def scene_pixel_rgb(driver, col, row):
    """The scene picture's RGB at a cell, read back through a canvas."""
    return driver.execute_script(
        "const i = document.getElementById('scene'); const c = document.createElement('canvas');"
        "c.width = i.naturalWidth; c.height = i.naturalHeight;"
        "const g = c.getContext('2d'); g.drawImage(i, 0, 0);"
        "return Array.from(g.getImageData(arguments[0], arguments[1], 1, 1).data.slice(0, 3));",
        col, row)


def overlays_drawn(driver):
    """Every overlay picture on screen: the plain ones shown with a picture,
    and the map's mask layers."""
    return driver.execute_script(
        "const out = [];"
        "for (const e of document.querySelectorAll('.overlay-img'))"
        "  if (getComputedStyle(e).display !== 'none' && e.getAttribute('src')) out.push(e.src);"
        "const map = document.getElementById('map');"
        "if (getComputedStyle(map).display !== 'none')"
        "for (const e of map.querySelectorAll('img.leaflet-image-layer'))"
        "  if (e.id !== 'map-image' && e.src.includes('/api/overlay/')) out.push(e.src);"
        "return out;")


def set_overlays(driver, names):
    for box in driver.find_elements("css selector", ".overlay"):
        if box.is_selected() != (box.get_attribute("value") in names):
            box.click()


def choose(driver, select_id, value):
    from selenium.webdriver.support.ui import Select
    Select(driver.find_element("id", select_id)).select_by_value(value)


def image_run(driver):
    return driver.execute_script(
        "const i = document.getElementById('image');"
        "return i.complete && i.naturalWidth > 0 ? i.dataset.run || '' : '';")


def check_map_furniture(driver, slant_rows):
    """After a click on the slant image: the scene's cursor marks the cell
    the inspector names, drawn over that cell; a click on the scene marks the
    slant pixel; the scale bar agrees with the cell size; the legend's colours
    are the scene picture's."""
    at = wait_until(lambda: cursor(driver, "scene-cursor", "scene"), 10, "the scene cursor")
    assert at[:2] == [int(slant_rows["scene col"]), int(slant_rows["scene row"])], (at, slant_rows)
    tx, ty = aim_tolerance(driver, "scene")
    assert abs(at[2] - at[0]) <= tx and abs(at[3] - at[1]) <= ty, f"drawn off its cell: {at}"
    print(f"linked cursor: slant ({slant_rows['bin']}, {slant_rows['line']}) -> scene "
          f"({at[0]}, {at[1]})")
    # Back: the scene cell, and the slant pixel it falls in is marked.
    driver.execute_script("document.getElementById('inspector').innerHTML = '';")
    click_pixel(driver, "scene", 300, 300)
    rows = wait_until(lambda: (i := inspector(driver)) and "pixel bin" in i and i, 30,
                      "the scene inspector with its slant pixel")
    back = wait_until(lambda: (c := cursor(driver, "image-cursor", "image"))
                      and c[:2] == [int(rows["pixel bin"]), int(rows["pixel line"])] and c, 10,
                      "the image cursor at the scene cell's pixel")
    tx, ty = aim_tolerance(driver, "image")
    assert abs(back[2] - back[0]) <= tx and abs(back[3] - back[1]) <= ty, back
    # The scale bar: its drawn length over its metres is the scene's shown
    # pixels per metre (shown width / cells / cell size).
    bar = driver.execute_script(
        "const b = document.getElementById('scene-scalebar'), i = document.getElementById('scene');"
        "const s = state.scene;"
        "return [Number(b.dataset.metres), b.querySelector('.bar').getBoundingClientRect().width,"
        "        i.getBoundingClientRect().width / i.naturalWidth / s.cell_m, s.cell_m];")
    metres, px, px_per_m, cell_m = bar
    assert abs(px / metres - px_per_m) <= 0.01 * px_per_m + 2.0 / metres, bar
    print(f"scale bar: {metres} m drawn {px:.1f} px (cell {cell_m:.3f} m)")
    # The legend names the clicked cell's category with the colour the
    # scene picture paints flat ground of it.
    legend = driver.execute_script(
        "return Array.from(document.querySelectorAll('#legend [data-category]'))"
        "  .map((e) => [Number(e.dataset.category), e.dataset.rgb.split(',').map(Number)]);")
    assert legend, "no legend"
    category = int(rows["category id"])
    colour = dict((c, rgb) for c, rgb in legend).get(category)
    assert colour is not None, (category, legend)
    rgb = scene_pixel_rgb(driver, 300, 300)
    assert max(abs(a - b) for a, b in zip(rgb, colour)) <= 12, (rgb, colour)
    assert driver.find_element("css selector", ".north").text.startswith("N")


def check_overlays(driver):
    """Every overlay on, then off: nothing drawn; through the presentations
    with shadow on: never a slant mask over another view."""
    set_overlays(driver, ["shadow", "layover", "backfacing"])
    drawn = wait_until(lambda: len(overlays_drawn(driver)) == 2 and overlays_drawn(driver), 30,
                       "the overlays")
    key = driver.execute_script(
        "return Array.from(document.querySelectorAll('#overlay-key [data-mask]'))"
        "  .map((e) => e.dataset.mask);")
    assert sorted(key) == ["backfacing", "layover", "shadow"], key
    set_overlays(driver, [])
    wait_until(lambda: overlays_drawn(driver) == [], 10, "every overlay off")
    assert not shown(driver, "image-overlay") and not shown(driver, "scene-overlay")
    print(f"overlays: {len(drawn)} pictures on, none after unchecking every box")
    set_overlays(driver, ["shadow"])
    wait_until(lambda: len(overlays_drawn(driver)) == 2, 30, "the shadow overlay")
    for view, expect in (("ground", None), ("geocoded", "geocoded"), ("slant", "slant")):
        choose(driver, "presentation", view)
        wait_until(lambda: driver.execute_script(
            "return document.getElementById('image').dataset.view") == view, 30, view)
        drawn = wait_until(lambda: (d := overlays_drawn(driver)) is not None and
                           len(d) == (1 if expect is None else 2) and d, 30,
                           f"the overlays of {view}")
        image_masks = [u for u in drawn if "/overlay/scene.png" not in u]
        if expect is None:
            assert image_masks == [], f"a stale overlay over {view}: {image_masks}"
        else:
            assert len(image_masks) == 1 and f"/overlay/{expect}.png" in image_masks[0], drawn
        driver.save_screenshot(os.path.join(os.environ.get("RIS_E2E_OUT", "."), f"view-{view}.png"))
    set_overlays(driver, [])


def check_linked_zoom(driver):
    """The geocoded map: zoomed in with its + button, the scene view shows the
    same place (centre within two cells); the map's scale bar agrees with its
    pixels per metre (a simple CRS in the scene's metres)."""
    choose(driver, "presentation", "geocoded")
    wait_until(lambda: shown(driver, "map"), 30, "the map")
    zoom0 = driver.execute_script("return map.getZoom();")
    # One click at a time: Leaflet ignores a click while the last zoom still
    # animates (seen under ASan, where the page is slower to settle).
    for step in (1, 2):
        driver.find_element("css selector", ".leaflet-control-zoom-in").click()
        wait_until(lambda: driver.execute_script("return map.getZoom();") >= zoom0 + step, 30,
                   "the map to zoom in")
    # And off the centre, as a drag would.
    driver.execute_script("map.panBy([90, -60], {animate: false});")
    def centres():
        return driver.execute_script(
            "const s = state.scene, c = map.getCenter();"
            "const v = document.getElementById('scene-viewport').getBoundingClientRect();"
            "const i = document.getElementById('scene'), r = i.getBoundingClientRect();"
            "return [c.lng / s.cell_m, s.rows - c.lat / s.cell_m,"
            "  (v.left + v.width / 2 - r.left) / r.width * i.naturalWidth,"
            "  (v.top + v.height / 2 - r.top) / r.height * i.naturalHeight, map.getZoom()];")
    middle = driver.execute_script("return [state.scene.cols / 2, state.scene.rows / 2];")
    c = wait_until(lambda: (c := centres()) and abs(c[0] - middle[0]) > 20 and
                   abs(c[0] - c[2]) <= 2 and abs(c[1] - c[3]) <= 2 and c, 10,
                   "the scene to follow the map")
    print(f"linked zoom: map centre ({c[0]:.1f}, {c[1]:.1f}) scene centre ({c[2]:.1f}, "
          f"{c[3]:.1f}) cells, zoom {c[4]}")
    bar = driver.execute_script(
        "const b = document.querySelector('.leaflet-control-scale-line');"
        "const a = map.latLngToContainerPoint([0, 0]), z = map.latLngToContainerPoint([0, 1000]);"
        "return [b.textContent, b.getBoundingClientRect().width, (z.x - a.x) / 1000];")
    text, px, px_per_m = bar
    metres = float(text.split()[0]) * (1000 if text.endswith("km") else 1)
    assert abs(px / metres - px_per_m) <= 0.02 * px_per_m, bar
    choose(driver, "presentation", "slant")
    double_click(driver, "scene-viewport")


def api_json(driver, path):
    """GET path from the page (same origin), as JSON."""
    return driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "fetch(arguments[0]).then((r) => r.json()).then(done, (e) => done({error: String(e)}));",
        path)


def set_frequency(driver, ghz):
    """Types a frequency as a person would; returns the new run's id."""
    from selenium.webdriver.common.keys import Keys
    before = image_run(driver)
    box = driver.find_element("id", "frequency")
    box.clear()
    box.send_keys(str(ghz), Keys.TAB)
    return wait_until(lambda: (r := image_run(driver)) and r != before and r, 60,
                      f"the run at {ghz} GHz")


def image_rect(driver, element_id):
    return driver.execute_script(
        "const r = document.getElementById(arguments[0]).getBoundingClientRect();"
        "return [r.left, r.top, r.width, r.height];", element_id)


def check_compare(driver, out_dir):
    """Two runs in two bands on the same grid: side by side shows both, the
    swipe shows the earlier run clipped at its slider, and the difference
    view's value at a pixel is 10 log10 of the two runs' powers there (read
    through the inspector API), drawn in its key's colour."""
    choose(driver, "presentation", "slant")
    earlier = set_frequency(driver, 9.6)
    current = set_frequency(driver, 13.5)
    wait_until(lambda: driver.execute_script(
        "return Array.from(document.getElementById('compare-run').options)"
        "  .some((o) => o.value === arguments[0]);", earlier), 30, "the earlier run listed")
    choose(driver, "compare-run", earlier)
    choose(driver, "compare-mode", "side")
    wait_until(lambda: shown(driver, "compare-image") and driver.execute_script(
        "const i = document.getElementById('compare-image');"
        "return i.complete && i.naturalWidth > 0 && i.dataset.run === arguments[0];", earlier),
        30, "the earlier run beside the current one")
    now, then = image_rect(driver, "image"), image_rect(driver, "compare-image")
    assert then[0] >= now[0] + now[2] - 1 and abs(then[2] - now[2]) < 1, (now, then)
    sizes = driver.execute_script(
        "const a = document.getElementById('image'), b = document.getElementById('compare-image');"
        "return [a.naturalWidth, a.naturalHeight, b.naturalWidth, b.naturalHeight];")
    assert sizes[:2] == sizes[2:], sizes
    driver.save_screenshot(os.path.join(out_dir, "7-compare-side.png"))
    choose(driver, "compare-mode", "swipe")
    wait_until(lambda: "inset" in driver.execute_script(
        "return document.getElementById('compare-image').style.clipPath;"), 10, "the swipe")
    then = image_rect(driver, "compare-image")
    now = image_rect(driver, "image")
    assert max(abs(a - b) for a, b in zip(now, then)) < 1, (now, then)
    driver.save_screenshot(os.path.join(out_dir, "8-compare-swipe.png"))
    choose(driver, "compare-mode", "difference")
    wait_until(lambda: shown(driver, "difference-image") and shown(driver, "difference-key")
               and driver.execute_script(
                   "const i = document.getElementById('difference-image');"
                   "return i.complete && i.naturalWidth > 0;"), 30, "the difference view")
    key = driver.execute_script(
        "const k = document.getElementById('difference-key');"
        "return [JSON.parse(k.dataset.key), Number(k.dataset.range)];")
    stops, range_db = key
    assert len(stops) == 11 and stops[0]["db"] == -range_db and stops[-1]["db"] == range_db, key
    driver.execute_script("document.getElementById('inspector').innerHTML = '';")
    col, row = 120, 350
    click_pixel(driver, "image", col, row)

    def difference_row():
        return driver.execute_script(
            "const td = document.querySelector('#inspector td[data-key=\"compare.difference_db\"]');"
            "const b = document.querySelector('#inspector td[data-key=\"bin\"]');"
            "const l = document.querySelector('#inspector td[data-key=\"line\"]');"
            "return td && b && l ? [td.dataset.value, Number(b.textContent),"
            "                       Number(l.textContent)] : null;")
    value, b, l = wait_until(difference_row, 30, "the difference in the inspector")
    xy = f"x={b}&y={l}"
    a = api_json(driver, f"/api/inspect?view=slant&{xy}")
    e = api_json(driver, f"/api/inspect?view=slant&run={earlier}&{xy}")
    expected = 10 * __import__("math").log10(a["mean_power_w"] / e["mean_power_w"])
    assert abs(float(value) - expected) <= 1e-6 * max(1.0, abs(expected)), (value, expected)
    # The difference picture's colour there is the key's at that value.
    rgb = driver.execute_script(
        "const i = document.getElementById('difference-image');"
        "const c = document.createElement('canvas'); c.width = i.naturalWidth;"
        "c.height = i.naturalHeight; const g = c.getContext('2d'); g.drawImage(i, 0, 0);"
        "return Array.from(g.getImageData(arguments[0], arguments[1], 1, 1).data);", b, l)
    t = min(10.0, max(0.0, 5 + 5 * expected / range_db))
    k = min(9, int(t))
    want = [stops[k]["rgb"][c] + (t - k) * (stops[k + 1]["rgb"][c] - stops[k]["rgb"][c])
            for c in range(3)]
    assert rgb[3] == 255 and max(abs(x - y) for x, y in zip(rgb, want)) <= 1, (rgb, want)
    print(f"compare: run {current} against run {earlier}: pixel ({b}, {l}) difference "
          f"{float(value):.4f} dB (inspector {expected:.4f} dB), colour {rgb[:3]} "
          f"(key {[round(x) for x in want]}), range +-{range_db} dB")
    driver.save_screenshot(os.path.join(out_dir, "9-compare-difference.png"))
    choose(driver, "compare-mode", "off")
    wait_until(lambda: not shown(driver, "difference-image") and not shown(driver, "compare-image"),
               10, "compare off")


def wheel(driver, viewport_id, img_id, clicks):
    """Zooms a viewport in by `clicks` wheel steps at a point of its picture
    off the picture's centre."""
    driver.execute_script(
        "const v = document.getElementById(arguments[0]).getBoundingClientRect();"
        "const i = document.getElementById(arguments[1]).getBoundingClientRect();"
        "const x0 = Math.max(v.left, i.left), x1 = Math.min(v.right, i.right);"
        "const y0 = Math.max(v.top, i.top), y1 = Math.min(v.bottom, i.bottom);"
        "const e = document.getElementById(arguments[0]);"
        "for (let k = 0; k < arguments[2]; ++k)"
        "  e.dispatchEvent(new WheelEvent('wheel', {deltaY: -100, bubbles: true,"
        "    cancelable: true, clientX: x0 + 0.45 * (x1 - x0), clientY: y0 + 0.55 * (y1 - y0)}));",
        viewport_id, img_id, clicks)


def view_centre(driver, viewport_id, img_id):
    """The image pixel at the viewport's centre and the visible span."""
    return driver.execute_script(
        "const v = document.getElementById(arguments[0]).getBoundingClientRect();"
        "const i = document.getElementById(arguments[1]), r = i.getBoundingClientRect();"
        "return [(v.left + v.width / 2 - r.left) / r.width * i.naturalWidth,"
        "        (v.top + v.height / 2 - r.top) / r.height * i.naturalHeight,"
        "        v.width / r.width * i.naturalWidth, v.height / r.height * i.naturalHeight];",
        viewport_id, img_id)


def check_slant_zoom(driver):
    """The slant view zooms with the scene (and the scene with it): zoomed in
    on one, the other's centre is the place the centre of the first images,
    by the inspector's geocoding; its orientation is labelled."""
    choose(driver, "presentation", "slant")
    wait_until(lambda: driver.execute_script(
        "return document.getElementById('image').dataset.view") == "slant", 30, "the slant view")
    label = driver.find_element("id", "image-orientation").text
    assert "flight" in label and "slant range" in label and "linked" in label, label
    for source, target in (("scene", "slant"), ("slant", "scene")):
        src_vp, src_img = (("scene-viewport", "scene") if source == "scene"
                           else ("image-viewport", "image"))
        dst_vp, dst_img = (("image-viewport", "image") if source == "scene"
                           else ("scene-viewport", "scene"))
        before = driver.execute_script(
            "return document.getElementById('image-viewport').dataset.linked || '';")
        wheel(driver, src_vp, src_img, 5)
        wait_until(lambda: driver.execute_script(
            "return (document.getElementById('image-viewport').dataset.linked || '')"
            "  .startsWith(arguments[0] + ':') && document.getElementById('image-viewport')"
            "  .dataset.linked !== arguments[1];", source, before), 30, f"{target} to follow")
        sx, sy, _, _ = view_centre(driver, src_vp, src_img)
        dx, dy, dw, dh = view_centre(driver, dst_vp, dst_img)
        full = driver.execute_script(
            "const i = document.getElementById(arguments[0]);"
            "return [i.naturalWidth, i.naturalHeight];", dst_img)
        assert dw < 0.8 * full[0] or dh < 0.8 * full[1], ("not zoomed", dw, dh, full)
        if source == "scene":
            cell = api_json(driver, f"/api/inspect?view=scene&x={int(sx)}&y={int(sy)}")
            assert "pixel" in cell, (sx, sy, cell)
            want = (cell["pixel"]["bin"], cell["pixel"]["line"])
            got = (dx, dy)
        else:
            px = api_json(driver, f"/api/inspect?view=slant&x={int(sx)}&y={int(sy)}")
            want = (px["scene_col"], px["scene_row"])
            got = (dx, dy)
        # Within a sixth of the span shown (the regions are bounding boxes
        # of a sampled mapping) and a few pixels.
        assert abs(got[0] - want[0]) <= dw / 6 + 3 and abs(got[1] - want[1]) <= dh / 6 + 3, \
            (source, got, want, dw, dh)
        print(f"slant zoom: {source} centre ({sx:.1f}, {sy:.1f}) -> {target} centre "
              f"({got[0]:.1f}, {got[1]:.1f}), geocoded ({want[0]}, {want[1]}), "
              f"span {dw:.0f} x {dh:.0f}")
    # Both back to the whole picture, unlinked (a linked reset would fit
    # one to the other's footprint).
    driver.find_element("id", "link-zoom").click()
    double_click(driver, "scene-viewport")
    double_click(driver, "image-viewport")
    driver.find_element("id", "link-zoom").click()


def double_click(driver, element_id):
    from selenium.webdriver.common.action_chains import ActionChains
    ActionChains(driver).double_click(driver.find_element("id", element_id)).perform()


def check_sensors(driver, out_dir):
    """The optical and thermal views: each a picture on the scene's grid
    (as many pixels as the scene image), another one at another time of day,
    and none once switched off."""
    def sensor_state():
        return driver.execute_script(
            "const i = document.getElementById('sensor-image');"
            "return [i.dataset.state || '', i.naturalWidth, i.naturalHeight, i.src, i.hidden];")

    scene_size = driver.execute_script(
        "const i = document.getElementById('scene'); return [i.naturalWidth, i.naturalHeight];")
    choose(driver, "sensor-kind", "optical")
    first = wait_until(lambda: (st := sensor_state())[0] == "ready" and st, 120,
                       "the optical view")
    assert first[1:3] == scene_size, (first, scene_size)
    driver.execute_script("const t = document.getElementById('sensor-time'); t.value = 1080;"
                          "t.dispatchEvent(new Event('change'));")
    evening = wait_until(lambda: (st := sensor_state())[0] == "ready" and st[3] != first[3]
                         and st, 120, "the optical view at 18:00")
    assert "minute=1080" in evening[3], evening
    choose(driver, "sensor-kind", "thermal")
    thermal = wait_until(lambda: (st := sensor_state())[0] == "ready" and "thermal" in st[3]
                         and st, 180, "the thermal view")
    assert thermal[1:3] == scene_size, thermal
    driver.save_screenshot(os.path.join(out_dir, "5-thermal.png"))
    choose(driver, "sensor-kind", "off")
    wait_until(lambda: sensor_state()[4], 10, "the sensor view switched off")
    print(f"sensor views: optical and thermal {thermal[1]} x {thermal[2]} px (the scene's), "
          "another picture at 18:00 UTC, off hides it")


def check_upload(driver, out_dir):
    """A DEM uploaded from the page, imported and simulated with the library
    it names; a scene cell's latitude and longitude lie inside the DEM."""
    dem = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "dem",
                       "SanAnd_dem.tif")
    run_before = image_run(driver)
    choose(driver, "upload-kind", "dem")
    driver.find_element("id", "upload-file").send_keys(os.path.abspath(dem))
    driver.find_element("id", "upload").click()
    note = wait_until(lambda: (t := driver.find_element("id", "upload-note").text) and t, 60,
                      "the upload")
    assert "generic-terrain.toml" in note, note
    wait_until(lambda: (r := image_run(driver)) and r != run_before, 60, "the DEM's image")
    driver.execute_script("document.getElementById('inspector').innerHTML = '';")
    click_pixel(driver, "scene", 50, 120)
    rows = wait_until(lambda: (i := inspector(driver)) and "latitude, deg" in i and i, 30,
                      "the inspector on the DEM")
    lat, lon = float(rows["latitude, deg"]), float(rows["longitude, deg"])
    # SanAnd_dem.tif: 34.140..34.210 N, 118.440..118.410 W (gdalinfo).
    assert 34.140 <= lat <= 34.211 and -118.441 <= lon <= -118.410, rows
    print(f"uploaded DEM: {note}; cell at {lat:.5f} N, {lon:.5f} E")
    driver.save_screenshot(os.path.join(out_dir, "5-uploaded-dem.png"))
    errors = driver.find_element("id", "error").text
    assert errors == "", f"the page shows an error: {errors}"


def check_without_libraries(ris_exe, out_dir):
    """Without Leaflet and Chart.js the page still shows the images, says
    what is missing, and the geocoded view is a plain picture."""
    work = tempfile.mkdtemp(prefix="ris-serve-e2e-nolib-")
    server = Server(ris_exe, os.path.join(work, "out"),
                    ("--javascript-dir", os.path.join(work, "none")))
    driver = None
    try:
        driver = make_driver(os.path.join(work, "profile"))
        driver.get(server.url + "/")
        wait_until(lambda: image_run(driver), 60, "the first image without libraries")
        note = driver.find_element("id", "lib-note").text
        assert "libjs-leaflet" in note and "libjs-chart.js" in note, note
        choose(driver, "presentation", "geocoded")
        wait_until(lambda: driver.execute_script(
            "return document.getElementById('image').dataset.view") == "geocoded", 30,
            "the plain geocoded image")
        assert shown(driver, "image") and not shown(driver, "map")
        driver.save_screenshot(os.path.join(out_dir, "6-without-libraries.png"))
        print(f"without libraries: {note}")
    finally:
        if driver is not None:
            driver.quit()
        server.stop()
        shutil.rmtree(work, ignore_errors=True)


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
    os.environ["RIS_E2E_OUT"] = out_dir
    work = tempfile.mkdtemp(prefix="ris-serve-e2e-")
    # The server's working folder (uploads) under a folder of the test's.
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp)
    server = Server(ris_exe, os.path.join(work, "out"), env={"TMPDIR": tmp})
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
        # A click lands within one screen pixel of its aim: in image pixels,
        # within the image pixels per screen pixel (the slant image is shown
        # in its true aspect, so lines may be narrower than bins).
        tx, ty = aim_tolerance(driver, "image")
        assert abs(int(rows["bin"]) - 120) <= tx and abs(int(rows["line"]) - 350) <= ty, rows
        check_map_furniture(driver, rows)
        check_overlays(driver)
        check_linked_zoom(driver)
        check_slant_zoom(driver)
        check_compare(driver, out_dir)

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
        set_overlays(driver, [])

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
        saved_text = open(path).read()
        assert "box" in saved_text
        # The new box is written in the scene's unit (feet), not metres.
        last = saved_text.rsplit("[[object]]", 1)[1]
        assert re.search(r"length = [\"']\d+ ft[\"']", last), last
        driver.save_screenshot(os.path.join(out_dir, "4-saved.png"))
        check_sensors(driver, out_dir)
        check_upload(driver, out_dir)
        errors = driver.find_element("id", "error").text
        assert errors == "", f"the page shows an error: {errors}"
    finally:
        if driver is not None:
            driver.quit()
        code, out = server.stop()
        left = [n for n in os.listdir(tmp) if n.startswith("ris-serve-")]
        shutil.rmtree(work, ignore_errors=True)
    assert code == 0, f"ris serve exit code {code} after SIGINT:\n{out}"
    # The uploads lived in the server's own working folder, gone with it.
    assert not left, f"the server left its working folder behind: {left}"
    check_without_libraries(ris_exe, out_dir)
    print(f"ok; screenshots in {out_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

// Drives the built page in headless Chromium for tests/web.rs, and prints one JSON object of what
// it saw; the Rust test makes the assertions. puppeteer-core is installed by the test (its
// version is in tests/web.rs).
//
//   node drive.mjs BASE_URL OUT_DIR PICKED_MESH DROPPED_FILE...
//
// Every scenario opens a new page; console errors and uncaught exceptions of all pages are
// collected. The page publishes its figures on the canvas's data-* attributes
// (crates/app/src/gui/platform/web.rs).

import { readFileSync } from "node:fs";
import { basename, join, resolve } from "node:path";
import puppeteer from "puppeteer-core";
import { dropSphere, sphereLoaded } from "./busy.mjs";

const [base, out, picked, ...dropped] = process.argv.slice(2);
const TIMEOUT = 60_000;
// Where "Open mesh…" is drawn at 1280 × 800 (CSS pixels).
const OPEN_MESH = { x: 72, y: 84 };

// A browser whose screen has `scale` device pixels per CSS pixel. (Emulating the scale per page,
// as puppeteer's deviceScaleFactor does, leaves the canvas's device-pixel size unscaled, so the
// app would draw at the wrong size: a real screen's scale is what a user has.)
const launch = (scale) =>
  puppeteer.launch({
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    args: [
      "--no-sandbox",
      "--use-angle=swiftshader",
      "--enable-unsafe-swiftshader",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
      `--force-device-scale-factor=${scale}`,
    ],
  });
const browsers = { 1: await launch(1), 1.5: await launch(1.5), 2: await launch(2) };

const result = { errors: [], failures: [], scenarios: {} };

// Runs one scenario; a failure is recorded with its message and the others still run.
async function scenario(name, body) {
  try {
    await body();
  } catch (e) {
    result.failures.push(`${name}: ${e.message}`);
  }
}

async function open(name, query, viewport = { width: 1280, height: 800 }, scale = 1) {
  const page = await browsers[scale].newPage();
  // deviceScaleFactor 0: the screen's own.
  await page.setViewport({ ...viewport, deviceScaleFactor: 0 });
  page.on("console", (m) => {
    if (m.type() === "error") result.errors.push(`${name}: ${m.text()}`);
  });
  page.on("pageerror", (e) => result.errors.push(`${name}: ${e.message}`));
  // A DataTransfer holding files given as [name, base64 bytes] (what a drop or a chooser gives).
  await page.evaluateOnNewDocument(() => {
    window.transfer = (files) => {
      const transfer = new DataTransfer();
      for (const [name, b64] of files) {
        const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        transfer.items.add(new File([bytes], name));
      }
      return transfer;
    };
  });
  // A query, or a whole address (the single file, opened from the disk).
  const address = query.startsWith("file://") ? query : base + query;
  await page.goto(address, { waitUntil: "load", timeout: TIMEOUT });
  await frames(page, 3);
  return page;
}

async function figures(page) {
  return page.$eval("#inertia-lab", (c) => ({ ...c.dataset, title: document.title }));
}

async function frames(page, n) {
  await page.waitForFunction(
    (n) => Number(document.getElementById("inertia-lab")?.dataset.frames ?? 0) >= n,
    { timeout: TIMEOUT, polling: 50 },
    n,
  );
}

// Waits until a load has finished and the title names `file`; if it does not, the page as it
// was is saved as failed-<file>.png beside the screenshots.
async function loaded(page, file) {
  try {
    await page.waitForFunction(
      (file) =>
        document.title === `Inertia Lab — ${file}` &&
        document.getElementById("inertia-lab").dataset.loading === "false",
      { timeout: TIMEOUT, polling: 50 },
      file,
    );
  } catch (e) {
    await page.screenshot({ path: join(out, `failed-${file}.png`) });
    throw e;
  }
  return figures(page);
}

// Files as [name, base64 bytes], to be made into File objects in the page by `transfer`.
const encoded = (paths) => paths.map((p) => [basename(p), readFileSync(p).toString("base64")]);

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// A point on the body: the 3D view's centre (the camera frames the body's centre of mass
// there) moved right by 1.5 % of the view's height, so that a poke along the view ray has a
// lever arm about the centre of mass. The book's inscribed sphere (radius 0.5 of its bounding
// sphere's 4.06) projects to a disc of about 5 % of the framed view's height around the centre,
// whatever the book's orientation: the point is on the book at any moment.
async function offCentre(page) {
  const [left, top, width, height] = (await figures(page)).view.split(" ").map(Number);
  return { x: left + width / 2 + 0.015 * height, y: top + height / 2 };
}

// 1. The page as opened: the T-handle, drawn and moving; a screenshot for the pixel checks; the
// live region's description, and whether the accessibility tree holds it.
await scenario("default", async () => {
  const page = await open("default", "/");
  const first = await figures(page);
  await sleep(3000);
  const later = await figures(page);
  await page.screenshot({ path: join(out, "page-1280x800.png") });
  // What a screen reader is given: the live region's words, found in Chromium's accessibility
  // tree (every node's name, the uninteresting ones included).
  const live = await page.$eval("#live", (e) => e.textContent);
  const tree = await page.accessibility.snapshot({ interestingOnly: false });
  const names = [];
  const walk = (node) => {
    if (!node) return;
    if (node.name) names.push(node.name);
    for (const child of node.children ?? []) walk(child);
  };
  walk(tree);
  const described = names.filter((n) => n.includes(live) && live.length > 0).length;
  result.scenarios.default = { first, later, live, described };
  await page.close();
});

// 2. A poke: |L| stays while nothing acts (torque-free; |ω| does not, the book having three
// different moments), and changes with a click on the body.
for (const [name, viewport, scale, touch] of [
  ["poke", { width: 1280, height: 800 }, 1, false],
  // A tablet: 1024 × 768 CSS pixels at 2 device pixels each, touch only.
  ["tap", { width: 1024, height: 768, isMobile: true, hasTouch: true }, 2, true],
]) {
  await scenario(name, async () => {
    const page = await open(name, "/?sample=book", viewport, scale);
    await frames(page, 10);
    const before = await figures(page);
    await sleep(500);
    const still = await figures(page);
    const at = await offCentre(page);
    if (touch) {
      await page.touchscreen.tap(at.x, at.y);
    } else {
      await page.mouse.click(at.x, at.y);
    }
    const clicked = Number((await figures(page)).frames);
    await frames(page, clicked + 5);
    const after = await figures(page);
    result.scenarios[name] = { before, still, after, at };
    await page.close();
  });
}

// 3. A link names the scene: sample, spin axis, comparison; a bad key is said, not fatal.
await scenario("link", async () => {
  const page = await open("link", "/?sample=tennis_racket&spin=2&compare=bbox");
  result.scenarios.link = await figures(page);
  await page.close();
  const bad = await open("bad_link", "/?sample=anvil&spin=7");
  result.scenarios.bad_link = await figures(bad);
  await bad.close();
});

// 3b. Every link in the page resolves: each address an element names (links, scripts, images,
// the icon) is fetched from the page; one on another site must answer too (no-cors: any answer).
await scenario("links", async () => {
  const page = await open("links", "/");
  result.scenarios.links = await page.evaluate(async () => {
    const urls = [...document.querySelectorAll("a[href], link[href], script[src], img[src], iframe[src]")]
      .map((e) => e.href || e.src);
    return Promise.all(
      urls.map(async (url) => {
        const local = new URL(url).origin === location.origin || url.startsWith("data:");
        try {
          const answer = await fetch(url, local ? {} : { mode: "no-cors" });
          return { url, ok: local ? answer.ok : true, status: answer.status };
        } catch (e) {
          return { url, ok: false, status: String(e) };
        }
      }),
    );
  });
  await page.close();
});

// 4. The file picker ("Open mesh…" at the top of the side panel: rfd's <input type=file>). A
// headless browser cancels a native file chooser at once, so the input's click is kept from
// opening one, and the file is put in the input as the chooser would put it (made in the page
// from its bytes, as the drop below: a file granted by path could not always be read here).
await scenario("picker", async () => {
  const page = await open("picker", "/");
  await page.evaluate(() => {
    const click = HTMLInputElement.prototype.click;
    HTMLInputElement.prototype.click = function () {
      if (this.type !== "file") click.call(this);
    };
  });
  await page.mouse.click(OPEN_MESH.x, OPEN_MESH.y);
  const input = await page.waitForSelector("#rfd-input", { timeout: TIMEOUT });
  await input.evaluate((input, files) => {
    input.files = transfer(files).files;
    input.dispatchEvent(new Event("change"));
  }, encoded([picked]));
  result.scenarios.picker = await loaded(page, basename(picked));
  await page.close();
});

// Drops files (as [name, base64 bytes]) on the page's canvas, as a person's drop arrives.
async function drop(page, files) {
  await page.evaluate((files) => {
    const dataTransfer = transfer(files);
    const canvas = document.getElementById("inertia-lab");
    for (const type of ["dragenter", "dragover", "drop"]) {
      canvas.dispatchEvent(new DragEvent(type, { dataTransfer, bubbles: true, cancelable: true }));
    }
  }, files);
}

// 5. Files dropped on the page: a body file with its meshes.
await scenario("drop", async () => {
  const page = await open("drop", "/");
  const files = encoded(dropped);
  await drop(page, files);
  const main = files.find(([n]) => n.endsWith(".toml"))?.[0] ?? files[0][0];
  result.scenarios.drop = await loaded(page, main);
  await page.close();
});

// 5b. A .gltf dropped with the .bin it names, the .bin first: the page reads the buffer from
// the files dropped together (DROP_GLTF: the two paths, colon-separated).
await scenario("drop_gltf", async () => {
  const page = await open("drop_gltf", "/");
  const files = encoded(process.env.DROP_GLTF.split(":"));
  await drop(page, files);
  result.scenarios.drop_gltf = await loaded(page, files.find(([n]) => n.endsWith(".gltf"))[0]);
  await page.close();
});

// 6. A big mesh dropped (a UV sphere of 2 × 600 × 300 triangles, binary STL made in the page):
// the page keeps drawing while the worker loads it, says the stage, and then shows the mesh's
// volume. The frames are recorded in the page (busy.mjs).
await scenario("busy", async () => {
  const page = await open("busy", "/");
  const volume = await page.evaluate(dropSphere, 600, 300);
  const frames = await sphereLoaded(page, TIMEOUT);
  result.scenarios.busy = { volume, shown: await figures(page), ...frames };
  await page.close();
});

// 6b. The same sphere dropped on a body of parts (the hammer of steel and wood) joins it as a
// part: read, summed and indexed in the worker while the page keeps drawing, then the body's
// volume is the hammer's and the sphere's.
await scenario("busy_part", async () => {
  const page = await open("busy_part", "/?sample=hammer.toml");
  await page.waitForFunction(() => document.title.toLowerCase().includes("hammer"), {
    timeout: TIMEOUT,
  });
  await sleep(1000);
  const before = await figures(page);
  const title = await page.title();
  const volume = await page.evaluate(dropSphere, 600, 300);
  const frames = await sphereLoaded(page, TIMEOUT, title);
  result.scenarios.busy_part = { volume, before, shown: await figures(page), ...frames };
  await page.close();
});

// 7. Record: five seconds of the page as PNG pictures, one .zip download (the test reads it).
// Record wraps under the plots' first row at 1280 × 800 (CSS pixels).
const RECORD = { x: 390, y: 636 };
await scenario("record", async () => {
  const page = await open("record", "/");
  // The browser's own session, with its events: the download is over when it says completed.
  // (A folder named with ".." cancels every download: resolved first.)
  const session = await browsers[1].target().createCDPSession();
  await session.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: resolve(out), eventsEnabled: true });
  let name;
  const done = new Promise((resolve, reject) => {
    session.on("Browser.downloadWillBegin", (e) => (name = e.suggestedFilename));
    session.on("Browser.downloadProgress", (e) => {
      if (e.state === "completed") resolve();
      if (e.state === "canceled") reject(new Error("the download was cancelled"));
    });
    setTimeout(() => reject(new Error("no recording was downloaded")), TIMEOUT);
  });
  const start = Date.now();
  await page.mouse.click(RECORD.x, RECORD.y);
  await done;
  result.scenarios.record = { archive: join(out, name), ms: Date.now() - start };
  await session.detach();
  await page.close();
});

// 7b. Fifty restarts by every route: the keys 1, 2, 3 and R, and the side panel's Spin axis and
// Reset buttons, each with the view holding the keys (Escape) and with a widget focused (Tab).
// After each, with no further input, the simulated time (data-time) starts again and runs on
// past half a second, the body turns (data-orientation) and the 3D view shows it turning. A restart once left the clock
// standing at 0.05–0.13 s until the next input event.
// The side panel's Motion section at 1280 × 800 (CSS pixels), as page-1280x800.png shows it.
const SPIN = [1, 2, 3].map((k) => ({ x: 63 + (k - 1) * 85, y: 746 }));
const RESET = { x: 159, y: 723 };
await scenario("restarts", async () => {
  const page = await open("restarts", "/");
  // The clock and orientation the page publishes, and the 3D view's pixels as shown (a page
  // that went on simulating but stopped presenting would show the same picture).
  const now = async () => {
    const f = await figures(page);
    const [x, y, width, height] = f.view.split(" ").map(Number);
    const shown = await page.screenshot({ clip: { x, y, width, height }, encoding: "base64" });
    return { time: Number(f.time), orientation: f.orientation.split(" ").map(Number), shown };
  };
  const routes = [
    ["key 1", () => page.keyboard.press("1")],
    ["key 2", () => page.keyboard.press("2")],
    ["key 3", () => page.keyboard.press("3")],
    ["key R", () => page.keyboard.press("r")],
    ...SPIN.map((at, k) => [`Spin axis ${k + 1}`, () => page.mouse.click(at.x, at.y)]),
    ["Reset", () => page.mouse.click(RESET.x, RESET.y)],
  ];
  const runs = [];
  // The page takes keys once it has been clicked: on the message line, where a click does nothing.
  await page.mouse.click(900, 10);
  for (let k = 0; k < 50; k++) {
    const [route, act] = routes[k % routes.length];
    const focused = Math.floor(k / routes.length) % 2 === 1;
    await page.keyboard.press(focused ? "Tab" : "Escape");
    await page.waitForFunction(() => Number(document.getElementById("inertia-lab").dataset.time) >= 0.5, {
      timeout: 10_000,
      polling: 20,
    });
    const before = await now();
    await act();
    const restarted = await page
      .waitForFunction((t) => Number(document.getElementById("inertia-lab").dataset.time) < t, { timeout: 5_000, polling: 10 }, before.time)
      .then(() => true, () => false);
    const start = await now();
    const ran = await page
      .waitForFunction(() => Number(document.getElementById("inertia-lab").dataset.time) >= 0.5, { timeout: 5_000, polling: 20 })
      .then(() => true, () => false);
    const end = await now();
    const turned = Math.hypot(...end.orientation.map((c, i) => c - start.orientation[i]));
    const redrawn = start.shown !== end.shown;
    runs.push({ route, focused, restarted, ran, start: start.time, end: end.time, turned, redrawn });
  }
  result.scenarios.restarts = runs;
  await page.close();
});

// 7c. Lesson 1 by the keyboard alone: L shows the lessons, Tab moves the focus (the page
// publishes which widget has it, as a screen reader is told), Enter presses or chooses. Nothing
// is clicked: a page that cannot be reached by Tab fails here.
await scenario("keyboard_lesson", async () => {
  const page = await open("keyboard_lesson", "/");
  const steps = [];
  // Tabs until the focused widget's name starts with `words` (egui describes it as "name: role"); then Enter.
  const choose = async (words) => {
    for (let k = 0; k < 250; k++) {
      await page.keyboard.press("Tab");
      await frames(page, Number((await figures(page)).frames) + 1);
      const focus = (await figures(page)).focus;
      if (focus.startsWith(words)) {
        await page.keyboard.press("Enter");
        await frames(page, Number((await figures(page)).frames) + 2);
        const f = await figures(page);
        steps.push({ words, tabs: k + 1, focus, lesson: f.lesson, step: f.lessonStep, title: f.title });
        return;
      }
    }
    throw new Error(`no widget named "${words}" within 250 Tabs`);
  };
  // The page's canvas takes the keys once it has the focus; the keyboard gives it that too.
  await page.focus("#inertia-lab");
  await page.keyboard.press("l");
  await choose("1. What the inertia tensor is");
  await choose("larger than the exact ones");
  await choose("Commit to my prediction");
  await choose("bounding box");
  await choose("Next step");
  await choose("exact");
  const end = await figures(page);
  const live = await page.$eval("#live", (e) => e.textContent);
  await page.screenshot({ path: join(out, "keyboard-lesson-done.png") });
  result.scenarios.keyboard_lesson = { steps, end, live };
  await page.close();
});

// 7d. The page in German and in Spanish (?lang=): the document's language, data-lang, and the
// live description in that language with a decimal comma; a screenshot of each.
for (const lang of ["de", "es"]) {
  await scenario(`lang_${lang}`, async () => {
    const page = await open(`lang_${lang}`, `/?lang=${lang}&lesson=3`);
    await sleep(1500);
    const f = await figures(page);
    const documentLang = await page.evaluate(() => document.documentElement.lang);
    const live = await page.$eval("#live", (e) => e.textContent);
    await page.screenshot({ path: join(out, `page-${lang}-1280x800.png`) });
    result.scenarios[`lang_${lang}`] = { figures: f, documentLang, live };
    await page.close();
  });
}

// 7d'. A teacher's lesson file beside the page, named by its address with a step.
await scenario("fetched_lesson", async () => {
  const page = await open("fetched_lesson", "/?lesson=class.lesson.toml&step=2");
  await page.waitForFunction(() => document.getElementById("inertia-lab").dataset.lesson === "class", {
    timeout: TIMEOUT,
    polling: 50,
  });
  result.scenarios.fetched_lesson = await figures(page);
  await page.close();
});

// 7e. The page as one file opened from the disk (SINGLE_FILE, made by web/single_file.py): it
// runs, and a file dropped on it loads in its worker (a blob the page made: nothing is beside it).
await scenario("single_file", async () => {
  const page = await open("single_file", `file://${process.env.SINGLE_FILE}`);
  await frames(page, 10);
  const first = await figures(page);
  await drop(page, encoded([picked]));
  const dropped = await loaded(page, basename(picked));
  result.scenarios.single_file = { first, dropped };
  await page.close();
});

// 8. A 1920 × 1080 display at 1.5 device pixels per CSS pixel, for a person to look at.
await scenario("hidpi", async () => {
  const page = await open("hidpi", "/?sample=tennis_racket&spin=2", { width: 1280, height: 720 }, 1.5);
  await sleep(2000);
  await page.screenshot({ path: join(out, "page-1920x1080.png") });
  await page.close();
});

for (const browser of Object.values(browsers)) await browser.close();
console.log(JSON.stringify(result));

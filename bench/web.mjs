// The page's figures in headless Chromium (software WebGL2: ANGLE on SwiftShader), each run in a
// fresh browser, medians and ranges printed as a Markdown table:
//
//   node bench/web.mjs URL [--runs N] [--mesh FILE]
//
// - first frame: milliseconds from navigation to the app's first frame (the page's
//   data-first-frame-ms: wasm fetched, compiled and started);
// - frame time: the app's own `?bench=300` line from the console (as --bench-frames prints it);
// - with --mesh: a mesh file dropped on the page (fetched from URL/FILE's name, so serve it
//   beside the site), milliseconds from the drop to the body shown: read, parse, analysis,
//   picking index, in the page's worker;
// - a 360k-triangle sphere (binary STL, 18 MB, made in the page: tests/web/busy.mjs) dropped:
//   milliseconds from the drop to the body shown, the frames the page drew meanwhile, those
//   drawn while the worker checked the mesh and built its picking index, and the page's longest
//   pause between two frames, all from the page's own record of its frames.
//
// puppeteer-core comes from the browser test's install (target/web-test/driver, made by
// `cargo test --test web`) or from PUPPETEER_DIR.

import { createRequire } from "node:module";
import { basename } from "node:path";
import { dropSphere, sphereLoaded } from "../tests/web/busy.mjs";

const driver = process.env.PUPPETEER_DIR ?? "target/web-test/driver";
const require = createRequire(`${process.cwd()}/${driver}/package.json`);
const puppeteer = require("puppeteer-core");

const args = process.argv.slice(2);
const url = args[0];
const option = (name, fallback) => {
  const k = args.indexOf(name);
  return k > 0 ? args[k + 1] : fallback;
};
const runs = Number(option("--runs", "5"));
const mesh = option("--mesh", null);

async function fresh(body) {
  const browser = await puppeteer.launch({
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
    ],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 800 });
    return await body(page);
  } finally {
    await browser.close();
  }
}

// Opens the page and waits until the app has drawn a few frames.
async function running(page) {
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => document.getElementById("inertia-lab").dataset.frames > 2, {
    timeout: 120_000,
  });
}

const canvas = (page, key) =>
  page.$eval("#inertia-lab", (c, key) => c.dataset[key], key);

const median = (v) => {
  const s = [...v].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const row = (name, v, unit) =>
  console.log(
    `| ${name} | ${median(v).toFixed(1)} ${unit} | ${Math.min(...v).toFixed(1)}–${Math.max(...v).toFixed(1)} ${unit} | ${v.length} |`,
  );

console.log("| measure | median | range | runs |\n|---|---|---|---|");

const first = [];
const frame = [];
const loads = [];
const busy = [];
for (let k = 0; k < runs; k++) {
  first.push(
    await fresh(async (page) => {
      await page.goto(url, { waitUntil: "load" });
      await page.waitForFunction(() => document.getElementById("inertia-lab").dataset.firstFrameMs, {
        timeout: 120_000,
      });
      return Number(await canvas(page, "firstFrameMs"));
    }),
  );
  frame.push(
    await fresh(async (page) => {
      const line = new Promise((resolve) =>
        page.on("console", (m) => m.text().startsWith("frames ") && resolve(m.text())),
      );
      await page.goto(`${url}?bench=300`, { waitUntil: "load" });
      const text = await line;
      return Number(/mean ([0-9.]+) ms/.exec(text)[1]);
    }),
  );
  if (mesh) {
    loads.push(
      await fresh(async (page) => {
        await running(page);
        const name = basename(mesh);
        return page.evaluate(async (name) => {
          const bytes = await (await fetch(name)).arrayBuffer();
          const dataTransfer = new DataTransfer();
          dataTransfer.items.add(new File([bytes], name));
          const canvas = document.getElementById("inertia-lab");
          const start = performance.now();
          canvas.dispatchEvent(new DragEvent("drop", { dataTransfer, bubbles: true, cancelable: true }));
          await new Promise((resolve) => {
            const poll = () =>
              document.title.endsWith(name) && canvas.dataset.loading === "false"
                ? resolve()
                : setTimeout(poll, 10);
            poll();
          });
          return performance.now() - start;
        }, name);
      }),
    );
  }
  busy.push(
    await fresh(async (page) => {
      await running(page);
      await page.evaluate(dropSphere, 600, 300);
      return sphereLoaded(page, 120_000);
    }),
  );
}
row("navigation → first frame", first, "ms");
row("frame time, default scene (?bench=300, mean)", frame, "ms");
const of = (key) => busy.map((b) => b[key]);
row("360k-triangle sphere dropped → shown (in the worker)", of("load_ms"), "ms");
row("  frames drawn meanwhile", of("frames_while_loading"), "");
row("  frames drawn while the worker checked and indexed it", of("worker_frames"), "");
row("  the page's longest pause between two frames", of("longest_pause_ms"), "ms");
if (mesh) row(`${basename(mesh)} dropped → shown`, loads, "ms");

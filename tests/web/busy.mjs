// A big mesh dropped on the page, and the page's own record of the frames the app drew while it
// loaded: shared by the browser test (tests/web/drive.mjs, which asserts what holds whatever the
// machine's load) and the benchmark (bench/web.mjs, which measures the figures that depend on it).
//
// The frames are recorded inside the page, where each frame happens, with its time: a script
// polling the canvas from Node sees neither frames nor pauses correctly when Node itself is
// starved of the CPU (issue 37: "0 frames in a load of 1925 ms, frozen for 685 ms at most").

// The stages the worker reports while it works (crates/app/src/lab/loader.rs, `Stage`'s words).
// A load on the page's own thread shows none of them in a drawn frame: the page draws nothing
// until the load is over.
const WORKER_STAGES = ["checking the mesh and its mass properties", "picking index"];

// In the page: makes a UV sphere of 2 × segments × rings triangles (less the poles' halves) as a
// binary STL, starts recording frames, drops the file on the canvas, and returns the volume the
// divergence theorem gives for the file's own f32 corners (in f64).
export function dropSphere(segments, rings) {
  const point = (i, j) => {
    const [theta, phi] = [(Math.PI * i) / rings, (2 * Math.PI * j) / segments];
    return [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)].map(Math.fround);
  };
  const triangles = [];
  for (let i = 0; i < rings; i++) {
    for (let j = 0; j < segments; j++) {
      const [a, b, c, d] = [point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)];
      if (i > 0) triangles.push([a, b, d]);
      if (i < rings - 1) triangles.push([b, c, d]);
    }
  }
  const bytes = new ArrayBuffer(84 + 50 * triangles.length);
  const view = new DataView(bytes);
  view.setUint32(80, triangles.length, true);
  let sixfold = 0;
  triangles.forEach((t, k) => {
    t.flat().forEach((x, n) => view.setFloat32(84 + 50 * k + 12 + 4 * n, x, true));
    const [[ax, ay, az], [bx, by, bz], [cx, cy, cz]] = t;
    sixfold += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  });

  // Every frame the app publishes its figures on the canvas, data-frames last: one observed
  // change of data-frames is one frame drawn, stamped with the page's clock when it happened.
  const canvas = document.getElementById("inertia-lab");
  const log = [];
  window.frameLog = log;
  new MutationObserver(() => {
    const d = canvas.dataset;
    log.push({ ms: performance.now(), frames: Number(d.frames), stage: d.stage, loading: d.loading });
  }).observe(canvas, { attributes: true, attributeFilter: ["data-frames"] });

  const dataTransfer = new DataTransfer();
  dataTransfer.items.add(new File([bytes], "sphere.stl"));
  window.dropMs = performance.now();
  for (const type of ["dragenter", "dragover", "drop"]) {
    canvas.dispatchEvent(new DragEvent(type, { dataTransfer, bubbles: true, cancelable: true }));
  }
  return sixfold / 6;
}

// In Node: waits until the dropped sphere is shown (the page's title is `title`: the sphere's
// when it opened as the body, the body's when it joined one as a part), then reads the page's
// record of its frames and sums it up (times in the page's milliseconds):
// - load_ms: from the drop to the first frame that shows the load over;
// - frames_while_loading: the frames drawn in that time;
// - worker_frames: those drawn while the page said the worker was checking the mesh or building
//   its picking index (none if the load ran on the page's thread);
// - longest_pause_ms: the longest time between two frames in that time (from the drop to the
//   first frame, between frames, to the frame that shows the load over);
// - stages: the stages the frames showed.
export async function sphereLoaded(page, timeout, title = "Inertia Lab — sphere.stl") {
  // A frame that shows the load, then one that shows it over: the drop is read by the page
  // before the load begins, so "not loading" alone is also true before it.
  await page.waitForFunction(
    (title) => {
      const log = window.frameLog;
      const began = log.findIndex((f) => f.loading === "true");
      return document.title === title && began >= 0 && log.slice(began).some((f) => f.loading === "false");
    },
    { timeout, polling: 100 },
    title,
  );
  const { log, dropMs } = await page.evaluate(() => ({ log: window.frameLog, dropMs: window.dropMs }));
  const began = log.findIndex((f) => f.loading === "true");
  const ended = log.findIndex((f, k) => k > began && f.loading === "false");
  if (began < 0 || ended < 0) throw new Error(`no frame showed the load (${log.length} frames recorded)`);
  const during = log.slice(began, ended);
  let pause = log[0].ms - dropMs;
  for (let k = 1; k <= ended; k++) pause = Math.max(pause, log[k].ms - log[k - 1].ms);
  return {
    load_ms: log[ended].ms - dropMs,
    frames_while_loading: during.length,
    worker_frames: during.filter((f) => WORKER_STAGES.includes(f.stage)).length,
    longest_pause_ms: pause,
    stages: [...new Set(during.map((f) => f.stage))],
  };
}

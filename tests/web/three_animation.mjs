// Plays a baked GLB with three.js in headless Chromium for tests/export_roundtrip.rs, and prints
// one JSON object of what three.js made of it; the Rust test makes the assertions. three and
// puppeteer-core are installed beside this file by the test (their versions are there).
//
//   node three_animation.mjs FILE.glb TIME...
//
// The page (served from this folder on 127.0.0.1) loads the file with GLTFLoader, reads the
// node's KHR_physics_rigid_bodies extension as GLTFLoader keeps it (userData.gltfExtensions),
// and poses the node with an AnimationMixer at each TIME (seconds): the node's quaternion
// (x, y, z, w) and position then.

import { createServer } from "node:http";
import { readFileSync } from "node:fs";
import { extname, join, normalize } from "node:path";
import { fileURLToPath } from "node:url";
import puppeteer from "puppeteer-core";

const [file, ...times] = process.argv.slice(2);
const here = fileURLToPath(new URL(".", import.meta.url));
const types = { ".js": "text/javascript", ".html": "text/html", ".glb": "model/gltf-binary" };
const page = `<!doctype html><script type="importmap">
{"imports": {"three": "/node_modules/three/build/three.module.js",
             "three/addons/": "/node_modules/three/examples/jsm/"}}
</script>
<script type="module">
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
window.play = async (times) => {
  const bytes = await (await fetch("/body.glb")).arrayBuffer();
  const gltf = await new GLTFLoader().parseAsync(bytes, "");
  let node = null;
  gltf.scene.traverse((o) => { if (o.isMesh && !node) node = o; });
  const clip = gltf.animations[0];
  const mixer = new THREE.AnimationMixer(gltf.scene);
  // Played once and held at its end, so that the last keyframe's time poses the last key (a
  // repeating action would wrap it to the first).
  const action = mixer.clipAction(clip);
  action.setLoop(THREE.LoopOnce, 1);
  action.clampWhenFinished = true;
  action.play();
  const poses = times.map((t) => {
    mixer.setTime(t);
    node.updateMatrixWorld(true);
    return { time: t, quaternion: node.quaternion.toArray(), position: node.position.toArray() };
  });
  return {
    revision: THREE.REVISION,
    clips: gltf.animations.length,
    duration: clip.duration,
    tracks: clip.tracks.map((k) => k.name),
    motion: node.userData.gltfExtensions?.KHR_physics_rigid_bodies?.motion ?? null,
    vertices: node.geometry.attributes.position.count,
    poses,
  };
};
window.ready = true;
</script>`;

const server = createServer((request, response) => {
  const path = new URL(request.url, "http://localhost").pathname;
  if (path === "/") {
    response.writeHead(200, { "content-type": "text/html" }).end(page);
  } else if (path === "/favicon.ico") {
    response.writeHead(204).end();
  } else if (path === "/body.glb") {
    response.writeHead(200, { "content-type": types[".glb"] }).end(readFileSync(file));
  } else {
    const local = normalize(join(here, path));
    try {
      const body = readFileSync(local);
      response.writeHead(200, { "content-type": types[extname(local)] ?? "text/plain" }).end(body);
    } catch {
      response.writeHead(404).end();
    }
  }
});
await new Promise((done) => server.listen(0, "127.0.0.1", done));
const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--no-first-run", "--disable-background-networking"],
});
const errors = [];
try {
  const tab = await browser.newPage();
  tab.on("pageerror", (e) => errors.push(e.message));
  tab.on("console", (m) => m.type() === "error" && errors.push(m.text()));
  await tab.goto(`http://127.0.0.1:${server.address().port}/`);
  await tab.waitForFunction(() => window.ready === true, { timeout: 60_000 });
  const seen = await tab.evaluate((t) => window.play(t), times.map(Number));
  console.log(JSON.stringify({ ...seen, errors }));
} finally {
  await browser.close();
  server.close();
}

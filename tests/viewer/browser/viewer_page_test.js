// ctest viewer:browser: the viewer page in headless Chromium, driven through
// the DevTools protocol by puppeteer-core (this folder's lockfile; `npm ci`
// here installs it, and no browser: it uses the system's Chromium).
//   node viewer_page_test.js PATHTRACER SCENE OUT_DIR
// Loads the page, waits for 8 spp, drags the camera, walks two BVH levels,
// inspects a pixel and flips to the library reference, checking the canvas
// after each step (not blank, overlay drawn) and saving a screenshot of each
// in OUT_DIR. Every wait is for a condition, bounded by a timeout.
// Exits 77 (ctest's skip) when Chromium or node_modules is missing.
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const SKIP = 77;
const [pathtracer, scene, outDir] = process.argv.slice(2);
const chromium = ['/usr/bin/chromium', '/usr/bin/chromium-browser'].find((p) => fs.existsSync(p));
if (!chromium) {
  console.log('SKIP: Chromium is not installed (/usr/bin/chromium): the viewer page is not tested in a browser');
  process.exit(SKIP);
}
let puppeteer;
try {
  puppeteer = require('puppeteer-core');
} catch (e) {
  console.log('SKIP: puppeteer-core is not installed: run `npm ci` in ' + __dirname + ' (.ci/run does)');
  process.exit(SKIP);
}

const TIMEOUT = 60000;
let failures = 0, passes = 0;
// What the page draws or writes after the state a wait saw (the next frame,
// the next status line) is read again, every 100 ms for up to 5 s, until it
// holds: a loaded machine is slow, not wrong.
async function eventually(read, holds) {
  let value = await read();
  for (let i = 0; i < 50 && !holds(value); ++i) {
    await new Promise((r) => setTimeout(r, 100));
    value = await read();
  }
  return value;
}

function check(ok, what) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what);
  ok ? ++passes : ++failures;
}

// The viewer on a free port; resolves with its URL once it prints it.
function startViewer() {
  const child = spawn(pathtracer, ['--view', scene, '--port', '0', '-r', '96', '72', '-s', '8', '-m', '3', '-t', '2'],
    { stdio: ['ignore', 'pipe', 'inherit'] });
  return new Promise((resolve, reject) => {
    let text = '';
    const timer = setTimeout(() => reject(new Error('the viewer printed no URL within 60 s')), TIMEOUT);
    child.stdout.on('data', (d) => {
      text += d;
      const m = text.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (m) { clearTimeout(timer); resolve({ child, url: m[0] }); }
    });
    child.on('exit', (code) => reject(new Error('the viewer exited with ' + code + ': ' + text)));
  });
}

// What the canvas shows: how many pixels differ from the first, how many have
// the overlay colours, and a hash to tell images apart.
function canvasFacts(page) {
  return page.evaluate(() => {
    const c = document.getElementById('canvas');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let distinct = 0, blue = 0, magenta = 0, hash = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] !== d[0] || d[i + 1] !== d[1] || d[i + 2] !== d[2]) ++distinct;
      if (d[i] < 90 && d[i + 1] > 140 && d[i + 2] > 220) ++blue;           // the BVH box, #3af
      if (d[i] > 220 && d[i + 1] < 40 && d[i + 2] > 220) ++magenta;       // the inspected path, #f0f
      hash = (hash * 31 + d[i] + 7 * d[i + 1] + 13 * d[i + 2]) | 0;
    }
    return { distinct, blue, magenta, hash, pixels: d.length / 4 };
  });
}

async function shot(page, name) {
  fs.mkdirSync(outDir, { recursive: true });
  await page.screenshot({ path: path.join(outDir, name + '.png') });
}

async function main() {
  const { child, url } = await startViewer();
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'pt-viewer-chromium-'));
  const browser = await puppeteer.launch({
    executablePath: chromium, headless: true, userDataDir: profile,
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1400, height: 900 });
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(e.message));
    await page.goto(url);

    // 1. The progressive render reaches 8 spp and shows an image.
    await page.waitForFunction(() => window.viewer.status && window.viewer.status.spp >= 8 &&
      window.viewer.shownVersion === window.viewer.status.version, { timeout: TIMEOUT });
    let facts = await eventually(() => canvasFacts(page), (f) => f.distinct > f.pixels / 2);
    check(facts.distinct > facts.pixels / 2, `render shown, not blank (${facts.distinct} of ${facts.pixels} pixels differ from the first)`);
    const status = await eventually(() => page.$eval('#status', (e) => e.textContent),
      (t) => /8\.0\/8 spp/.test(t) && /Mrays\/s/.test(t));
    check(/8\.0\/8 spp/.test(status) && /Mrays\/s/.test(status), 'status line shows spp and rays/s: ' + status);
    await shot(page, '1_render');
    const rendered = facts.hash;

    // 2. Dragging the camera orbits it: a new camera, a new image.
    const before = await page.evaluate(() => [JSON.stringify(window.viewer.status.camera), window.viewer.status.generation]);
    const box = await (await page.$('#canvas')).boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    for (let i = 1; i <= 5; ++i) await page.mouse.move(box.x + box.width / 2 + 12 * i, box.y + box.height / 2 + 4 * i);
    await page.mouse.up();
    await page.waitForFunction((b) => JSON.stringify(window.viewer.status.camera) !== b[0] &&
      window.viewer.status.generation > b[1] && window.viewer.status.state === 'done' && window.viewer.shownVersion === window.viewer.status.version,
    { timeout: TIMEOUT }, before);
    facts = await eventually(() => canvasFacts(page), (f) => f.hash !== rendered && f.distinct > f.pixels / 2);
    check(facts.hash !== rendered && facts.distinct > facts.pixels / 2, 'camera drag: the view changed and the image is not blank');
    await shot(page, '2_orbit');

    // 3. BVH walk: root, then two levels down the left side: the first by
    // the L key with the focus still on the radio button just clicked.
    await page.click('input[value=bvh]');
    await page.waitForFunction(() => window.viewer.bvh && window.viewer.bvh.path === '', { timeout: TIMEOUT });
    await page.keyboard.press('l');
    const keyed = await page.waitForFunction(() => window.viewer.bvh.path === 'l', { timeout: 5000 }).then(() => true, () => false);
    check(keyed, 'the L key walks the tree right after a click on the "BVH walk" radio button');
    if (!keyed) await page.click('#bvh-left');
    await page.waitForFunction(() => window.viewer.bvh.path === 'l', { timeout: TIMEOUT });
    await page.click('#bvh-left');
    await page.waitForFunction(() => window.viewer.bvh.path === 'll', { timeout: TIMEOUT });
    const info = await eventually(() => page.$eval('#bvh-info', (e) => e.textContent),
      (t) => /depth 2/.test(t) && /SAH/.test(t));
    check(/depth 2/.test(info) && /SAH/.test(info), 'BVH walk two levels down: ' + info);
    facts = await eventually(() => canvasFacts(page), (f) => f.blue > 20);
    check(facts.blue > 20, `the node's box is drawn over the image (${facts.blue} box-coloured pixels)`);
    await shot(page, '3_bvh');

    // 4. Pixel inspector: click the middle of the image, read the path.
    await page.click('input[value=inspect]');
    await page.mouse.click(box.x + box.width / 2, box.y + box.height * 0.6);
    await page.waitForFunction(() => window.viewer.path !== null && window.viewer.path.vertices, { timeout: TIMEOUT });
    const text = await eventually(() => page.$eval('#pixel-info', (e) => e.textContent),
      (t) => /(sphere|triangle) #\d+/.test(t) && /8 samples/.test(t));
    const rows = await page.$$eval('#pixel-info tr', (r) => r.length - 1);
    check(rows >= 1 && /(sphere|triangle) #\d+/.test(text) && /8 samples/.test(text), `pixel path read: ${rows} vertices`);
    facts = await eventually(() => canvasFacts(page), (f) => f.magenta > 5);
    check(facts.magenta > 5, `the path is drawn over the image (${facts.magenta} path-coloured pixels)`);
    await shot(page, '4_inspector');

    // 5. Flip to the library's reference image.
    await page.click('#flip');
    await page.waitForFunction(() => window.viewer.show === 'reference' && window.viewer.shownVersion === -2 &&
      window.viewer.image && window.viewer.image.width === 256, { timeout: TIMEOUT });
    facts = await eventually(() => canvasFacts(page), (f) => f.distinct > f.pixels / 2);
    check(facts.distinct > facts.pixels / 2, 'reference shown (256x192), not blank');
    await shot(page, '5_reference');

    check(pageErrors.length === 0, 'no script errors on the page' + (pageErrors.length ? ': ' + pageErrors.join('; ') : ''));

    // 6. Closing the page stops the render (its pagehide beacon): restart a
    // long render, close the page, and wait for the server to say stopped.
    await page.evaluate(() => fetch('/api/settings', { method: 'POST', body: JSON.stringify({ samples: 100000 }) }));
    await page.close({ runBeforeUnload: true });
    let state = '';
    for (let i = 0; i < 300 && state !== 'stopped'; ++i) {
      state = (await (await fetch(url + 'api/status')).json()).state;
      if (state !== 'stopped') await new Promise((r) => setTimeout(r, 100));
    }
    check(state === 'stopped', 'closing the page stopped the render (state ' + state + ')');
  } finally {
    await browser.close();
    fs.rmSync(profile, { recursive: true, force: true });
    child.kill('SIGINT');
  }
  const code = await new Promise((resolve) => child.on('exit', (c) => resolve(c)));
  check(code === 0, 'the viewer exited cleanly on Ctrl-C (status ' + code + ')');
  console.log(`${passes} passed, ${failures} failed`);
  process.exit(failures ? 1 : 0);
}

main().catch((e) => {
  console.log('FAIL ' + e.stack);
  process.exit(1);
});

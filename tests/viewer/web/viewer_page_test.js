// The viewer's page (viewer/web/viewer.js) in headless Chromium, from file:// with no server:
// a 12 s walk recorded with --record-view loads without console errors, shows a robot at t = 0
// and at t = 10 s, and the two screenshots differ where the robot is; a pushed run that falls
// has its fall on the timeline and the fall badge at the recorded fall time; a learner run
// replays the episode chosen, with its state in the panel.
// node --experimental-websocket viewer_page_test.js STRIDE SOURCE_DIR SCRATCH_DIR
'use strict';
const assert = require('assert/strict');
const {execFileSync, spawnSync} = require('child_process');
const fs = require('fs');
const path = require('path');
const {launch, decode_png} = require('./headless.js');

const [stride, source, scratch] = process.argv.slice(2);
fs.rmSync(scratch, {recursive: true, force: true});
fs.mkdirSync(scratch, {recursive: true});
const walk = path.join(source, 'models', 'walk.xml');

function run_and_view(name, args, system = walk) {
  const dir = path.join(scratch, name);
  execFileSync(stride, ['run', system, '--record-view', '--quiet', '-o', dir, ...args]);
  const r = spawnSync(stride, ['view', dir, '--quiet']);
  assert.equal(r.status, 0, r.stderr.toString());
  return 'file://' + path.join(dir, 'view.html');
}

// pixels of two equal-sized screenshots that differ inside a box
function differing(a, b, box) {
  let n = 0;
  for (let y = box.top; y <= box.bottom; ++y) {
    for (let x = box.left; x <= box.right; ++x) {
      const i = 4 * (y * a.width + x);
      if (Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1]) +
          Math.abs(a.data[i + 2] - b.data[i + 2]) > 30) ++n;
    }
  }
  return n;
}

async function main() {
  const walk_page = run_and_view('walk', ['--stop-time', '12']);
  // a constant 2 N sideways push topples the walking robot within a second
  const fall_page = run_and_view('fall', ['--stop-time', '3', '--set', 'robot.push_y=2']);
  // the demo learner cut to 2 episodes of 3 RL steps
  const learn_page = run_and_view(
      'learn', ['--no-plots', '--set', 'learner.total_steps=6', '--set', 'learner.steps_per_episode=3'],
      path.join(source, 'models', 'experiments', 'demo.xml'));
  const browser = await launch({width: 800, height: 600});
  try {
    const shots = [];
    for (const t of [0, 10]) {
      assert.equal(await browser.open(walk_page + '#t=' + t), 'ready');
      const time = await browser.evaluate(
          'JSON.parse(document.getElementById("stride-data").textContent).frames.t' +
          '[stride_view.frame()]');
      assert.ok(time <= t && time > t - 0.07, `frame shown for t = ${t}: ${time}`);
      const mask = await browser.evaluate('stride_view.robot_mask()');
      // the robot (0.45 m tall, 1.6 m from the camera in an 800x600 view) covers thousands of
      // pixels; the camera follows it, so it stays in the middle
      assert.ok(mask.count > 3000, `robot pixels at t = ${t}: ${mask.count}`);
      const centre = (mask.left + mask.right) / 2 / mask.width;
      assert.ok(centre > 0.3 && centre < 0.7, `robot centre at t = ${t}: ${centre}`);
      const png = await browser.screenshot();
      fs.writeFileSync(path.join(scratch, `walk-t${t}.png`), png);
      shots.push({png: decode_png(png), mask});
    }
    const [a, b] = shots;
    const box = {left: Math.min(a.mask.left, b.mask.left), right: Math.max(a.mask.right, b.mask.right),
                 top: Math.min(a.mask.top, b.mask.top), bottom: Math.max(a.mask.bottom, b.mask.bottom)};
    const area = (box.right - box.left + 1) * (box.bottom - box.top + 1);
    const changed = differing(a.png, b.png, box);
    // mid-stride at 10 s against the standing start: the legs, arms and path move
    assert.ok(changed > 0.05 * area, `pixels changed around the robot: ${changed} of ${area}`);

    assert.equal(await browser.open(fall_page), 'ready');
    const data = await browser.evaluate(
        'JSON.parse(document.getElementById("stride-data").textContent)');
    assert.equal(data.falls.length, 1, 'one fall recorded');
    const fall = data.falls[0];
    assert.ok(fall > 0 && fall < 3, `fall time ${fall}`);
    assert.equal(await browser.evaluate('document.querySelectorAll(".fall-mark").length'), 1);
    const left = await browser.evaluate('parseFloat(document.querySelector(".fall-mark").style.left)');
    const end = data.frames.t[data.frames.t.length - 1];
    // CSS keeps three decimals of the percentage
    assert.ok(Math.abs(left - 100 * fall / end) < 2e-3, `fall mark at ${left} %`);
    assert.equal(await browser.open(fall_page + '#t=' + (fall - 0.1)), 'ready');
    assert.equal(await browser.evaluate('document.body.dataset.fallen'), '0', 'before the fall');
    assert.equal(await browser.open(fall_page + '#t=' + fall), 'ready');
    assert.equal(await browser.evaluate('document.body.dataset.fallen'), '1', 'at the fall');
    assert.equal(await browser.evaluate(
        'getComputedStyle(document.getElementById("fall-badge")).display'), 'inline-block');
    fs.writeFileSync(path.join(scratch, 'fall.png'), await browser.screenshot());

    // a learner run: choose episode 2, its first frame is shown with the state of that moment
    assert.equal(await browser.open(learn_page + '#t=0'), 'ready');
    const learn = await browser.evaluate(
        'JSON.parse(document.getElementById("stride-data").textContent)');
    assert.equal(learn.episodes.length, 2);
    const second = learn.episodes[1];
    await browser.evaluate('const s = document.getElementById("episode"); s.value = "1";' +
                           's.dispatchEvent(new Event("change")); 0');
    const k = await browser.evaluate('stride_view.frame()');
    assert.ok(learn.frames.t[k] <= second.from && learn.frames.t[k] > second.from - 0.07,
              `episode 2 starts at ${second.from}, shown ${learn.frames.t[k]}`);
    const period = learn.state.find((s) => s.name === 'gait.period_time');
    assert.ok(period, 'gait.period_time in the state');
    const shown = await browser.evaluate(
        '[...document.querySelectorAll("#state tr")].map((r) => r.textContent)');
    assert.ok(shown.includes('gait.period_time' + period.values[k]), shown.join('; '));
    // episode 1 played at 8x stops where episode 2 begins
    await browser.evaluate('const e = document.getElementById("episode"); e.value = "0";' +
                           'e.dispatchEvent(new Event("change"));' +
                           'document.getElementById("speed").value = "8";' +
                           'document.getElementById("speed").dispatchEvent(new Event("change"));' +
                           'stride_view.play(true); 0');
    const last = learn.frames.t.findLastIndex((t) => t <= learn.episodes[0].to + 1e-9);
    assert.ok(last < learn.frames.t.length - 1);
    const until = Date.now() + 20000;
    while (await browser.evaluate('stride_view.frame()') < last && Date.now() < until) {
      await new Promise((r) => setTimeout(r, 100));
    }
    assert.equal(await browser.evaluate('stride_view.frame()'), last, 'stopped at the end');

    assert.deepEqual(browser.errors, [], 'console errors');
  } finally {
    await browser.close();
  }
  console.log('viewer page: ok');
}

main().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});

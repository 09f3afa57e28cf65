// Frame rate of a view page playing in headless Chromium (software WebGL): requestAnimationFrame
// callbacks over `seconds` of playback at 1x, for the page given. Prints "fps N".
// node --experimental-websocket playback_fps.js PAGE.html [seconds]
'use strict';
const path = require('path');
const {launch} = require('../../tests/viewer/web/headless.js');

async function main() {
  const page = 'file://' + path.resolve(process.argv[2]);
  const seconds = Number(process.argv[3] || 3);
  const browser = await launch({width: 1280, height: 720});
  try {
    if (await browser.open(page + '#t=0&play') !== 'ready') throw new Error('page failed');
    const before = await browser.evaluate('stride_view.animation_frames()');
    const start = Date.now();
    await new Promise((r) => setTimeout(r, seconds * 1000));
    const after = await browser.evaluate('stride_view.animation_frames()');
    const frame = await browser.evaluate('stride_view.frame()');
    if (frame === 0) throw new Error('the page did not play');
    console.log('fps ' + ((after - before) / ((Date.now() - start) / 1000)).toFixed(1));
  } finally {
    await browser.close();
  }
}
main().catch((e) => { console.error(e.stack || String(e)); process.exit(1); });

// Headless Chromium driven over the DevTools protocol (node's WebSocket, no npm package): load a
// page, evaluate in it, take screenshots, collect console errors. Shared by the viewer's page
// test and its benchmark. Needs the Debian package `chromium` (scripts/install-deps.sh); without
// it launch() throws, so a test fails instead of passing silently.
'use strict';
const {spawn, execFileSync} = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const zlib = require('zlib');

function find_chromium() {
  const names = [process.env.STRIDE_CHROMIUM, 'chromium', 'chromium-browser', 'google-chrome'];
  for (const name of names.filter(Boolean)) {
    try {
      return execFileSync('sh', ['-c', 'command -v "$0"', name]).toString().trim();
    } catch (e) {
      // try the next name
    }
  }
  throw new Error('headless Chromium not found (Debian package chromium; scripts/install-deps.sh ' +
                  'installs it, STRIDE_CHROMIUM names another binary)');
}

// Chromium normally reports its DevTools endpoint within a second. A start that hangs (seen once
// in CI under load, with nothing on stderr) is killed, described and tried again: the page test
// is about the viewer, not about one stuck browser start.
const START_ATTEMPTS = 3;
const START_TIMEOUT_MS = 30000;

function spawn_chromium(profile, width, height) {
  // software WebGL (SwiftShader): the same pixels on any machine, no GPU needed
  return spawn(find_chromium(), [
    '--headless', '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader',
    '--enable-unsafe-swiftshader', '--no-first-run', '--disable-extensions',
    '--disable-dev-shm-usage', '--remote-debugging-port=0', `--user-data-dir=${profile}`,
    `--window-size=${width},${height}`, 'about:blank'],
    {stdio: ['ignore', 'ignore', 'pipe'], detached: true});
}

// state and kernel wait channel of every process of the group: where a hung start waits
function describe_group(pid) {
  try {
    return execFileSync('ps', ['-g', String(pid), '-o', 'pid,stat,wchan:32,etime,args'])
        .toString();
  } catch (e) {
    return '(ps failed: ' + e.message + ')';
  }
}

function kill_group(proc) {
  try {
    process.kill(-proc.pid, 'SIGKILL');
  } catch (e) {
    // already gone
  }
}

function await_endpoint(proc) {
  return new Promise((resolve, reject) => {
    let text = '';
    const timer = setTimeout(() => {
      const where = describe_group(proc.pid);
      kill_group(proc);
      reject(new Error(`chromium did not start in ${START_TIMEOUT_MS / 1000} s; stderr: ` +
                       text + '\nprocesses:\n' + where));
    }, START_TIMEOUT_MS);
    proc.stderr.on('data', (chunk) => {
      text += chunk.toString();
      const m = /DevTools listening on (ws:\/\/\S+)/.exec(text);
      if (m) { clearTimeout(timer); resolve(m[1]); }
    });
    proc.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error('chromium exited (' + code + '): ' + text));
    });
  });
}

// a fresh profile per attempt: a killed start may leave its profile locked
async function start_chromium(width, height) {
  for (let attempt = 1;; ++attempt) {
    const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'stride-chromium-'));
    const proc = spawn_chromium(profile, width, height);
    try {
      return {proc, profile, endpoint: await await_endpoint(proc)};
    } catch (e) {
      fs.rmSync(profile, {recursive: true, force: true});
      if (attempt === START_ATTEMPTS) throw e;
      process.stderr.write(`attempt ${attempt} of ${START_ATTEMPTS}: ${e.message}\n`);
    }
  }
}

async function launch({width = 1000, height = 700} = {}) {
  if (typeof WebSocket === 'undefined') {
    throw new Error('node has no WebSocket: run it with --experimental-websocket (node >= 20.10)');
  }
  const {proc, profile, endpoint} = await start_chromium(width, height);
  const ws = new WebSocket(endpoint);
  await new Promise((resolve, reject) => { ws.onopen = resolve; ws.onerror = reject; });
  let next_id = 1;
  const pending = new Map();
  const listeners = [];
  ws.onmessage = (event) => {
    const msg = JSON.parse(event.data);
    if (msg.id && pending.has(msg.id)) {
      const {resolve, reject} = pending.get(msg.id);
      pending.delete(msg.id);
      if (msg.error) reject(new Error(JSON.stringify(msg.error))); else resolve(msg.result);
    } else if (msg.method) {
      for (const l of listeners) l(msg);
    }
  };
  const send = (method, params = {}, sessionId) => new Promise((resolve, reject) => {
    const id = next_id++;
    pending.set(id, {resolve, reject});
    ws.send(JSON.stringify({id, method, params, sessionId}));
  });
  const {targetId} = await send('Target.createTarget', {url: 'about:blank'});
  const {sessionId} = await send('Target.attachToTarget', {targetId, flatten: true});
  const errors = [];
  listeners.push((m) => {
    if (m.sessionId !== sessionId) return;
    if (m.method === 'Runtime.exceptionThrown') {
      errors.push(m.params.exceptionDetails.exception?.description ||
                  m.params.exceptionDetails.text);
    } else if (m.method === 'Runtime.consoleAPICalled' && m.params.type === 'error') {
      errors.push(m.params.args.map((a) => a.value ?? a.description).join(' '));
    } else if (m.method === 'Log.entryAdded' && m.params.entry.level === 'error') {
      errors.push(m.params.entry.text + ' (' + (m.params.entry.url || '') + ')');
    }
  });
  const page = (method, params) => send(method, params, sessionId);
  await page('Runtime.enable');
  await page('Log.enable');
  await page('Page.enable');
  await page('Emulation.setDeviceMetricsOverride',
             {width, height, deviceScaleFactor: 1, mobile: false});

  async function evaluate(expression) {
    const r = await page('Runtime.evaluate', {expression, awaitPromise: true, returnByValue: true});
    if (r.exceptionDetails) {
      throw new Error('in page: ' + (r.exceptionDetails.exception?.description ||
                                     r.exceptionDetails.text));
    }
    return r.result.value;
  }

  return {
    errors,
    evaluate,
    // loads `url` and waits until body[data-status] is no longer "loading"
    async open(url, timeout_ms = 30000) {
      // a new document each time, also when only the #fragment differs
      await page('Page.navigate', {url: 'about:blank'});
      await page('Page.navigate', {url});
      const start = Date.now();
      for (;;) {
        const status = await evaluate('document.body ? document.body.dataset.status : ""')
                           .catch(() => '');
        if (status && status !== 'loading') return status;
        if (Date.now() - start > timeout_ms) throw new Error(url + ': still loading');
        await new Promise((r) => setTimeout(r, 50));
      }
    },
    async screenshot() {
      const {data} = await page('Page.captureScreenshot', {format: 'png'});
      return Buffer.from(data, 'base64');
    },
    async close() {
      const exited = proc.exitCode !== null ? Promise.resolve()
                                            : new Promise((r) => proc.once('exit', r));
      send('Browser.close').catch(() => {});
      const timer = setTimeout(() => proc.kill('SIGKILL'), 5000);
      await exited;
      clearTimeout(timer);
      ws.close();
      fs.rmSync(profile, {recursive: true, force: true});
    },
  };
}

// RGBA pixels of an 8-bit RGB or RGBA PNG (what Chromium writes): {width, height, data}
function decode_png(buffer) {
  let at = 8;
  let width = 0, height = 0, channels = 0;
  const idat = [];
  while (at < buffer.length) {
    const length = buffer.readUInt32BE(at);
    const type = buffer.toString('ascii', at + 4, at + 8);
    const body = buffer.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      if (body[8] !== 8 || (body[9] !== 2 && body[9] !== 6) || body[12] !== 0) {
        throw new Error('decode_png: only 8-bit RGB/RGBA, not interlaced');
      }
      channels = body[9] === 6 ? 4 : 3;
    } else if (type === 'IDAT') {
      idat.push(body);
    }
    at += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const out = Buffer.alloc(width * height * 4);
  let prev = Buffer.alloc(stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = Buffer.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? line[i - channels] : 0;
      const b = prev[i];
      const c = i >= channels ? prev[i - channels] : 0;
      let v = 0;
      if (filter === 1) v = a;
      else if (filter === 2) v = b;
      else if (filter === 3) v = (a + b) >> 1;
      else if (filter === 4) {
        const p = a + b - c;
        const pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
        v = pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
      }
      line[i] = (line[i] + v) & 255;
    }
    for (let x = 0; x < width; ++x) {
      for (let ch = 0; ch < 4; ++ch) {
        out[(y * width + x) * 4 + ch] = ch < channels ? line[x * channels + ch] : 255;
      }
    }
    prev = line;
  }
  return {width, height, data: out};
}

module.exports = {launch, decode_png, find_chromium};

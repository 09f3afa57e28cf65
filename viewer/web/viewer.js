// The run viewer's page: reads the inlined data, imports the inlined three.js module through a
// blob URL (works from file://, no network), draws the robot posed by fk.js, and plays the
// frames. body[data-status] says "ready" or "error" (tests and the benchmark read it);
// window.stride_view exposes seek/state for them, window.stride_fk(frame) the FK link positions.
(function () {
  'use strict';

  function fail(message) {
    document.body.dataset.status = 'error';
    const box = document.getElementById('error');
    box.hidden = false;
    box.textContent = 'stride view: ' + message;
  }
  window.addEventListener('error', (e) => fail(e.message || String(e)));
  window.addEventListener('unhandledrejection', (e) => fail(String(e.reason)));

  const data = JSON.parse(document.getElementById('stride-data').textContent);
  const fk = window.stride_fk_lib;
  const frames = data.frames;
  const n = frames.t.length;

  // link positions of frame k in the world, for tests comparing with the plant
  window.stride_fk = (k) => fk.link_positions(data.model, fk.frame_poses(data.model, frames, k));

  const source = document.getElementById('three-src').textContent;
  const url = URL.createObjectURL(new Blob([source], {type: 'text/javascript'}));
  import(url).then((THREE) => start(THREE)).catch((e) => fail(e.stack || String(e)));

  function param(name) {
    const m = new RegExp('[#&]' + name + '(?:=([^&]*))?').exec(location.hash);
    return m ? (m[1] === undefined ? '' : decodeURIComponent(m[1])) : null;
  }

  // index of the last frame at or before time t
  function frame_at(t) {
    let lo = 0, hi = n - 1;
    if (t <= frames.t[0]) return 0;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (frames.t[mid] <= t + 1e-9) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  function shape_mesh(THREE, s, material) {
    let geometry;
    let turn = false;  // three's cylinders and capsules run along y, URDF's along z
    if (s.type === 'box') {
      geometry = new THREE.BoxGeometry(s.size[0], s.size[1], s.size[2]);
    } else if (s.type === 'cylinder') {
      geometry = new THREE.CylinderGeometry(s.size[0], s.size[0], s.size[1], 24);
      turn = true;
    } else if (s.type === 'capsule') {
      geometry = new THREE.CapsuleGeometry(s.size[0], s.size[1], 6, 16);
      turn = true;
    } else if (s.type === 'mesh') {
      return null;  // the page carries no triangles; the body's other shapes still show
    } else {
      geometry = new THREE.SphereGeometry(s.size[0], 20, 14);
    }
    const mesh = new THREE.Mesh(geometry, material);
    mesh.matrixAutoUpdate = false;
    const m = pose_matrix(THREE, s.origin);
    if (turn) m.multiply(new THREE.Matrix4().makeRotationX(Math.PI / 2));
    mesh.matrix.copy(m);
    return mesh;
  }

  function pose_matrix(THREE, p) {
    const R = p.R;
    return new THREE.Matrix4().set(R[0], R[1], R[2], p.p[0], R[3], R[4], R[5], p.p[1], R[6],
                                   R[7], R[8], p.p[2], 0, 0, 0, 1);
  }

  function start(THREE) {
    const view = document.getElementById('view');
    const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    view.appendChild(renderer.domElement);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0x1d2229);
    const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 200);
    camera.up.set(0, 0, 1);  // the plant's world is z-up
    scene.add(new THREE.HemisphereLight(0xdfe8f0, 0x30302a, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(2, -3, 5);
    scene.add(sun);

    // floor with a 0.1 m grid (1 m lines brighter), around the travelled area
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (let k = 0; k < n; ++k) {
      x0 = Math.min(x0, frames.x[k]); x1 = Math.max(x1, frames.x[k]);
      y0 = Math.min(y0, frames.y[k]); y1 = Math.max(y1, frames.y[k]);
    }
    const size = Math.ceil(Math.max(x1 - x0, y1 - y0, 1) + 2);
    const cx = Math.round((x0 + x1) / 2), cy = Math.round((y0 + y1) / 2);
    const floor = new THREE.Mesh(new THREE.PlaneGeometry(size, size),
                                 new THREE.MeshStandardMaterial({color: 0x3a4148}));
    floor.position.set(cx, cy, -0.0005);
    scene.add(floor);
    for (const [step, color] of [[0.1, 0x4b545d], [1, 0x8a96a3]]) {
      const grid = new THREE.GridHelper(size, Math.round(size / step), color, color);
      grid.rotation.x = Math.PI / 2;  // GridHelper lies in x-z
      grid.position.set(cx, cy, step === 1 ? 0.0004 : 0.0002);
      scene.add(grid);
    }

    // the travelled path: the whole run faint, the part up to now bright
    const path_points = [];
    for (let k = 0; k < n; ++k) path_points.push(new THREE.Vector3(frames.x[k], frames.y[k], 0.001));
    const path_geometry = new THREE.BufferGeometry().setFromPoints(path_points);
    scene.add(new THREE.Line(path_geometry, new THREE.LineBasicMaterial({color: 0x5c6f82})));
    const done_geometry = new THREE.BufferGeometry().setFromPoints(path_points);
    scene.add(new THREE.Line(done_geometry, new THREE.LineBasicMaterial({color: 0xffc107})));

    // falls: a red ring on the floor where the robot was, and a mark on the timeline
    for (const f of data.falls) {
      const k = frame_at(f);
      const ring = new THREE.Mesh(new THREE.RingGeometry(0.06, 0.08, 32),
                                  new THREE.MeshBasicMaterial({color: 0xe53935}));
      ring.position.set(frames.x[k], frames.y[k], 0.002);
      scene.add(ring);
      const mark = document.createElement('div');
      mark.className = 'fall-mark';
      mark.title = 'fall at t = ' + f + ' s';
      mark.style.left = (100 * (f - frames.t[0]) / Math.max(frames.t[n - 1] - frames.t[0], 1e-9)) + '%';
      document.getElementById('track').appendChild(mark);
    }

    // the robot: one group per body, posed every frame
    const materials = [new THREE.MeshStandardMaterial({color: 0x9aa7b4, roughness: 0.6}),
                       new THREE.MeshStandardMaterial({color: 0x6d7b8a, roughness: 0.6})];
    const root_material = new THREE.MeshStandardMaterial({color: 0x3d7bd9, roughness: 0.5});
    const bodies = data.model.bodies.map((b, i) => {
      const g = new THREE.Group();
      g.matrixAutoUpdate = false;
      const material = i === 0 ? root_material : materials[i % 2];
      for (const s of b.shapes) {
        const mesh = shape_mesh(THREE, s, material);
        if (mesh) g.add(mesh);
      }
      scene.add(g);
      return g;
    });

    // ---- state and controls
    const el = (id) => document.getElementById(id);
    const slider = el('slider');
    slider.max = String(n - 1);
    let k = 0, playing = false, speed = 1, time = frames.t[0];
    let range = [0, n - 1];  // frames of the chosen episode (all by default)
    let orbit = {azimuth: -2.2, elevation: 0.35, distance: 1.6};
    const target = new THREE.Vector3(frames.x[0], frames.y[0], 0.2);
    el('title').textContent = data.title;

    if (data.parameters.length > 0) {
      el('params-box').hidden = false;
      el('params').textContent = data.parameters.join('\n');
      el('params').style.whiteSpace = 'pre';
    }
    const state_rows = data.state.map((s) => {
      const row = document.createElement('tr');
      row.innerHTML = '<td></td><td class="v"></td>';
      row.firstChild.textContent = s.name;
      el('state').appendChild(row);
      return row.lastChild;
    });
    if (data.state.length > 0) el('state-box').hidden = false;
    if (data.episodes.length > 0) {
      const select = el('episode');
      select.hidden = false;
      select.innerHTML = '<option value="-1">whole run</option>';
      data.episodes.forEach((e, i) => {
        const o = document.createElement('option');
        o.value = String(i);
        o.textContent = e.label + ' (' + e.from + '–' + e.to + ' s)';
        select.appendChild(o);
      });
      select.addEventListener('change', () => choose_episode(Number(select.value)));
    }

    function choose_episode(i) {
      if (i < 0) {
        range = [0, n - 1];
      } else {
        const e = data.episodes[i];
        range = [frame_at(e.from), frame_at(e.to)];
      }
      seek(range[0]);
    }

    function resize() {
      const w = view.clientWidth, h = view.clientHeight;
      renderer.setSize(w, h);
      camera.aspect = w / Math.max(h, 1);
      camera.updateProjectionMatrix();
    }
    window.addEventListener('resize', resize);
    resize();

    function show(index) {
      k = Math.max(0, Math.min(n - 1, index));
      const poses = fk.frame_poses(data.model, frames, k);
      poses.forEach((p, i) => bodies[i].matrix.copy(pose_matrix(THREE, p)));
      done_geometry.setDrawRange(0, k + 1);
      slider.value = String(k);
      const fallen = frames.fallen ? frames.fallen[k] : 0;
      document.body.dataset.fallen = fallen ? '1' : '0';
      document.body.dataset.frame = String(k);
      el('p-time').textContent = frames.t[k].toFixed(3);
      el('time').textContent = frames.t[k].toFixed(2) + ' / ' + frames.t[n - 1].toFixed(2) + ' s';
      el('p-speed').textContent = String(speed);
      el('p-roll').textContent = (frames.roll[k] * 180 / Math.PI).toFixed(1);
      el('p-pitch').textContent = (frames.pitch[k] * 180 / Math.PI).toFixed(1);
      el('p-xy').textContent = frames.x[k].toFixed(3) + ', ' + frames.y[k].toFixed(3);
      data.state.forEach((s, i) => { state_rows[i].textContent = String(s.values[k]); });
    }

    function seek(index) {
      show(index);
      time = frames.t[k];
      render();
    }

    function render() {
      if (el('follow').checked) target.set(frames.x[k], frames.y[k], 0.2);
      const c = Math.cos(orbit.elevation);
      camera.position.set(target.x + orbit.distance * c * Math.cos(orbit.azimuth),
                          target.y + orbit.distance * c * Math.sin(orbit.azimuth),
                          target.z + orbit.distance * Math.sin(orbit.elevation));
      camera.lookAt(target);
      renderer.render(scene, camera);
    }

    function set_playing(on) {
      playing = on;
      el('play').textContent = on ? '▮▮' : '▶';
      if (on && k >= range[1]) seek(range[0]);
    }

    let last = null;
    let animation_frames = 0;
    function tick(now) {
      ++animation_frames;
      if (playing && last !== null) {
        time += speed * (now - last) / 1000;
        let next = frame_at(time);
        if (next >= range[1]) { next = range[1]; set_playing(false); }
        if (next !== k) show(next);
      }
      last = now;
      render();
      requestAnimationFrame(tick);
    }

    el('play').addEventListener('click', () => set_playing(!playing));
    el('back').addEventListener('click', () => { set_playing(false); seek(k - 1); });
    el('fwd').addEventListener('click', () => { set_playing(false); seek(k + 1); });
    el('speed').addEventListener('change', () => { speed = Number(el('speed').value); show(k); });
    slider.addEventListener('input', () => seek(Number(slider.value)));
    el('follow').addEventListener('change', render);
    window.addEventListener('keydown', (e) => {
      if (e.key === ' ') { set_playing(!playing); e.preventDefault(); }
      if (e.key === 'ArrowLeft') { set_playing(false); seek(k - 1); }
      if (e.key === 'ArrowRight') { set_playing(false); seek(k + 1); }
      if (e.key === 'f') { el('follow').checked = !el('follow').checked; render(); }
    });
    // orbit: drag turns the camera around the target, the wheel moves it closer or further
    let drag = null;
    renderer.domElement.addEventListener('pointerdown', (e) => { drag = [e.clientX, e.clientY]; });
    window.addEventListener('pointerup', () => { drag = null; });
    window.addEventListener('pointermove', (e) => {
      if (!drag) return;
      orbit.azimuth -= (e.clientX - drag[0]) * 0.008;
      orbit.elevation = Math.max(-0.1, Math.min(1.5, orbit.elevation + (e.clientY - drag[1]) * 0.008));
      drag = [e.clientX, e.clientY];
      render();
    });
    renderer.domElement.addEventListener('wheel', (e) => {
      orbit.distance = Math.max(0.2, Math.min(30, orbit.distance * Math.exp(e.deltaY * 0.001)));
      render();
      e.preventDefault();
    }, {passive: false});

    // the robot alone, white on black: how many pixels it covers and where (screen pixels,
    // top-left origin), for tests
    function robot_mask() {
      const hidden = scene.children.filter((c) => !bodies.includes(c) && c.visible && !c.isLight);
      hidden.forEach((c) => { c.visible = false; });
      const background = scene.background;
      scene.background = new THREE.Color(0x000000);
      scene.overrideMaterial = new THREE.MeshBasicMaterial({color: 0xffffff});
      render();
      const gl = renderer.getContext();
      const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
      const px = new Uint8Array(w * h * 4);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
      scene.overrideMaterial = null;
      scene.background = background;
      hidden.forEach((c) => { c.visible = true; });
      render();
      let count = 0, left = w, right = -1, top = h, bottom = -1;
      for (let y = 0; y < h; ++y) {
        for (let x = 0; x < w; ++x) {
          if (px[4 * (y * w + x)] < 128) continue;
          ++count;
          const row = h - 1 - y;
          left = Math.min(left, x); right = Math.max(right, x);
          top = Math.min(top, row); bottom = Math.max(bottom, row);
        }
      }
      return {count, left, right, top, bottom, width: w, height: h};
    }

    // for tests and the benchmark
    window.stride_view = {
      robot_mask,
      seek_time: (t) => seek(frame_at(t)),
      frame: () => k,
      frames: n,
      play: (on) => set_playing(on),
      animation_frames: () => animation_frames,
      set_speed: (s) => { speed = s; },
    };

    // #t=SECONDS opens paused at that time, #play plays from there, #speed=S sets the speed
    function apply_hash() {
      if (param('speed') !== null) {
        speed = Number(param('speed'));
        el('speed').value = String(speed);
      }
      const t0 = param('t');
      seek(t0 !== null ? frame_at(Number(t0)) : 0);
      set_playing(param('play') !== null || t0 === null);
    }
    apply_hash();
    window.addEventListener('hashchange', apply_hash);
    requestAnimationFrame(tick);
    document.body.dataset.status = 'ready';
  }
})();

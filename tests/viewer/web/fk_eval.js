// node fk_eval.js FK_JS DATA_JSON: the world position of every link for every frame of DATA_JSON
// ({"model", "frames"} as stride view writes them) by the viewer's FK, one line per link:
// "frame link x y z" with 17 significant digits. Used by tests/viewer/fk_test.cpp.
'use strict';
const fs = require('fs');
const fk = require(process.argv[2]);
const data = JSON.parse(fs.readFileSync(process.argv[3], 'utf8'));
const lines = [];
for (let k = 0; k < data.frames.t.length; ++k) {
  const links = fk.link_positions(data.model, fk.frame_poses(data.model, data.frames, k));
  for (const [name, p] of Object.entries(links)) {
    lines.push([k, name, ...p.map((v) => v.toPrecision(17))].join(' '));
  }
}
process.stdout.write(lines.join('\n') + '\n');

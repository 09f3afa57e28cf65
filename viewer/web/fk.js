// Forward kinematics of the run viewer, in float64: the pose of every body of the robot model
// (stride view's "model" JSON: the plant's robot_model, fixed joints merged) for one recorded
// frame. The rule is robot_model::forward_kinematics: the root body at the recorded base pose
// (R = Rz(yaw)·Ry(pitch)·Rx(roll)), then in joint order child = parent · origin · motion(q).
// Plain script: the page uses it as `stride_fk_lib`, node (tests) through require().
(function (root, factory) {
  const api = factory();
  if (typeof module === 'object' && module.exports) {
    module.exports = api;
  } else {
    root.stride_fk_lib = api;
  }
})(typeof self !== 'undefined' ? self : this, function () {
  'use strict';

  // a pose is {R: row-major 3x3, p: [x, y, z]}
  function compose(a, b) {
    const r = new Array(9);
    for (let i = 0; i < 3; ++i) {
      for (let j = 0; j < 3; ++j) {
        r[3 * i + j] =
            a.R[3 * i] * b.R[j] + a.R[3 * i + 1] * b.R[3 + j] + a.R[3 * i + 2] * b.R[6 + j];
      }
    }
    const p = [0, 0, 0];
    for (let i = 0; i < 3; ++i) {
      p[i] = a.R[3 * i] * b.p[0] + a.R[3 * i + 1] * b.p[1] + a.R[3 * i + 2] * b.p[2] + a.p[i];
    }
    return {R: r, p: p};
  }

  // rotation by q about the unit axis (Rodrigues, as Eigen::AngleAxis)
  function axis_angle(axis, q) {
    const [x, y, z] = axis;
    const c = Math.cos(q), s = Math.sin(q), t = 1 - c;
    return [
      t * x * x + c, t * x * y - s * z, t * x * z + s * y,
      t * x * y + s * z, t * y * y + c, t * y * z - s * x,
      t * x * z - s * y, t * y * z + s * x, t * z * z + c,
    ];
  }

  // R = Rz(yaw)·Ry(pitch)·Rx(roll), the plant's base orientation
  function rpy(roll, pitch, yaw) {
    const cr = Math.cos(roll), sr = Math.sin(roll);
    const cp = Math.cos(pitch), sp = Math.sin(pitch);
    const cy = Math.cos(yaw), sy = Math.sin(yaw);
    return [
      cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
      -sp, cp * sr, cp * cr,
    ];
  }

  function joint_motion(joint, q) {
    if (joint.type === 'prismatic') {
      return {R: [1, 0, 0, 0, 1, 0, 0, 0, 1], p: joint.axis.map((a) => a * q)};
    }
    return {R: axis_angle(joint.axis, q), p: [0, 0, 0]};
  }

  // joint positions of frame k by model joint: a servo joint reads its recorded column, a
  // passive joint (no servo ID, not recorded) stays at 0
  function joint_positions(model, frames, k) {
    return model.joints.map((j) => {
      const column = j.servo > 0 ? frames.q[j.servo - 1] : null;
      return column ? column[k] : 0;
    });
  }

  // world pose of every body for root pose `root` and joint positions `q` (by model joint)
  function body_poses(model, root, q) {
    const identity = {R: [1, 0, 0, 0, 1, 0, 0, 0, 1], p: [0, 0, 0]};
    const poses = model.bodies.map(() => identity);
    if (!model.fixed_base && poses.length > 0) poses[0] = root;
    model.joints.forEach((j, n) => {
      const parent = j.parent >= 0 ? poses[j.parent] : identity;
      poses[j.child] = compose(compose(parent, j.origin), joint_motion(j, q[n]));
    });
    return poses;
  }

  function frame_root(frames, k) {
    return {
      R: rpy(frames.roll[k], frames.pitch[k], frames.yaw[k]),
      p: [frames.x[k], frames.y[k], frames.z[k]],
    };
  }

  // body poses of recorded frame k
  function frame_poses(model, frames, k) {
    return body_poses(model, frame_root(frames, k), joint_positions(model, frames, k));
  }

  // world origin of every URDF link, {name: [x, y, z]}, from body poses
  function link_positions(model, poses) {
    const out = {};
    for (const l of model.links) {
      if (l.body < 0) continue;
      out[l.name] = compose(poses[l.body], l.in_body).p;
    }
    return out;
  }

  return {compose, axis_angle, rpy, joint_positions, body_poses, frame_poses, link_positions};
});

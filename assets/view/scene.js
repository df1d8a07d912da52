// eulerdyn view: the 3D scene. Space axes are three.js world axes with z up; the moment center O is the origin.
// The body group turns by the run's attitude q (body -> space) and holds the body's shape, point masses and body
// axes, all placed in body axes from O. Vectors are drawn in space axes: ω, H and M from a point beside the body
// (vectorAnchor), the bearing forces from the bearings. Wheels ([[body.rotor]]) turn with the body: a disc and its
// spin axis, and an arrow of the wheel's axial momentum h along the axis at H's scale. Moving masses
// ([[body.moving_mass]]) are balls in the body where their position columns put them at the time shown.
'use strict';

window.eulerdynScene = function (THREE, OrbitControls, api) {
  const geometry = api.geometry;
  const canvas = document.getElementById('scene');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xf4f5f7, 1);
  renderer.autoClear = false;
  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 1.2));
  const sun = new THREE.DirectionalLight(0xffffff, 2.0);
  sun.position.set(3, -2, 5);
  scene.add(sun);

  const v3 = (a) => new THREE.Vector3(a[0], a[1], a[2]);
  const quat = (q) => new THREE.Quaternion(q[1], q[2], q[3], q[0]);

  const body = new THREE.Group();
  scene.add(body);
  const shape = makeShape(THREE, geometry);
  body.add(shape);
  // What show(part, visible) hides and shows.
  const parts = { body: [shape], axes: [], vectors: [] };
  const bodyRadius = Math.max(1e-6, new THREE.Box3().setFromObject(shape).getBoundingSphere(new THREE.Sphere()).radius +
    v3(geometry.body.center || [0, 0, 0]).length());
  const samples = bodySamples(THREE, shape);
  for (const p of geometry.point_masses || []) {
    const ball = new THREE.Mesh(new THREE.SphereGeometry(0.07 * bodyRadius, 20, 12),
      new THREE.MeshStandardMaterial({ color: 0x333844, roughness: 0.4 }));
    ball.position.copy(v3(p.at));
    body.add(ball);
    parts.body.push(ball);
    samples.push(v3(p.at));
  }
  // The moving masses: a ball each, placed every frame from its position (reference origin) shifted to O.
  const referenceO = v3(geometry.reference_o || [0, 0, 0]);
  const movingBalls = (api.moving_names || []).map((name, k) => {
    const ball = new THREE.Mesh(new THREE.SphereGeometry(0.07 * bodyRadius, 20, 12),
      new THREE.MeshStandardMaterial({ color: 0xb0413e, roughness: 0.4 }));
    ball.name = 'moving mass ' + name;
    const last = api.rows[api.rows.length - 1];
    samples.push(v3(api.rows[0].moving[k]).add(referenceO), v3(last.moving[k]).add(referenceO));
    ball.position.copy(v3(api.rows[0].moving[k]).add(referenceO));
    body.add(ball);
    parts.body.push(ball);
    return ball;
  });
  api.moving_balls = movingBalls;
  const bodyBox = new THREE.Box3().setFromObject(body);
  const size = Math.max(bodyBox.getBoundingSphere(new THREE.Sphere()).radius + bodyBox.getCenter(new THREE.Vector3()).length(), 1e-6);

  // Body axes at C, turning with the body; space axes at O.
  const c = v3(geometry.mass_center || [0, 0, 0]);
  parts.axes.push(axesLines(THREE, 1.3 * size, c, 0.7, ['x_b', 'y_b', 'z_b']));
  parts.axes.push(axesLines(THREE, 2.1 * size, new THREE.Vector3(), 1.0, ['x_s', 'y_s', 'z_s']));
  body.add(parts.axes[0]);
  scene.add(parts.axes[1]);

  const q0 = quat(api.rows[0].q);
  // The fixed axis and its bearings, drawn where they are at t = 0; in a turning carrier (motion.carrier) the group
  // turns each frame by the shortest rotation taking the axis at t = 0 to the axis now, R(q(t)) a_b.
  const axisGroup = new THREE.Group();
  scene.add(axisGroup);
  const bearings = addAxisAndBearings(THREE, axisGroup, geometry, q0, size);
  const axisB = geometry.axis_b ? v3(geometry.axis_b).normalize() : null;
  const axis0 = axisB && axisB.clone().applyQuaternion(q0);
  api.axis_group = axisGroup;

  // Each kind of vector scaled so that its longest value over the run is 1.3 body sizes long.
  const longest = {};
  for (const name of api.vectors) {
    const look = window.eulerdynVectors[name];
    if (!look) continue;
    let max = 0;
    for (const row of api.rows) max = Math.max(max, Math.hypot(...row[name]));
    longest[look.kind] = Math.max(longest[look.kind] || 0, max);
  }
  // The wheels' momenta share H's scale.
  for (const row of api.rows) for (const h of row.rotor_h) longest.H = Math.max(longest.H || 0, Math.abs(h));
  const scaleOf = (name) => {
    const max = longest[window.eulerdynVectors[name].kind];
    return max > 0 ? (1.3 * size) / max : 0;
  };

  // The first view: from (4.3, −3.6, 2.6) body sizes with z up — or, with gravity, the same turned so that −g is up.
  const up = geometry.gravity_s ? v3(geometry.gravity_s).normalize().negate() : new THREE.Vector3(0, 0, 1);
  const turn = new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 0, 1), up);
  const camera = new THREE.PerspectiveCamera(40, 1, size / 100, size * 100);
  camera.up.copy(up);
  camera.position.set(4.3 * size, -3.6 * size, 2.6 * size).applyQuaternion(turn);
  const target = up.clone().multiplyScalar(0.6 * size);

  // ω, H and M start from a point beside the body (a small grey ball), not from O, so that they do not lie over it.
  const anchor = vectorAnchor(THREE, api, samples, size, scaleOf, camera.position.clone().sub(target), up);
  api.vector_origin = [anchor.x, anchor.y, anchor.z];
  const anchorBall = new THREE.Mesh(new THREE.SphereGeometry(0.025 * size, 16, 8),
    new THREE.MeshStandardMaterial({ color: 0x5a6070, roughness: 0.5 }));
  anchorBall.position.copy(anchor);
  scene.add(anchorBall);
  parts.vectors.push(anchorBall);

  const arrows = {};
  for (const name of api.vectors) {
    const look = window.eulerdynVectors[name];
    if (!look) continue;
    const arrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, look.color);
    arrow.line.material.linewidth = 2;
    if (look.kind !== 'R' && look.kind !== 'direction') arrow.position.copy(anchor);
    if (name === 'R_A_s' && bearings) arrow.position.copy(bearings[0]);
    if (name === 'R_B_s' && bearings) arrow.position.copy(bearings[1]);
    scene.add(arrow);
    arrows[name] = arrow;
    parts.vectors.push(arrow);
  }

  const wheels = makeWheels(THREE, geometry, api, size);
  parts.rotors = [];
  for (const w of wheels) {
    body.add(w.wheel, w.arrow);
    parts.rotors.push(w.wheel, w.arrow);
  }
  api.rotors = wheels;

  const trail = makeTrail(THREE, api, scaleOf, anchor);
  if (trail) scene.add(trail);
  const polhode = makePolhode(THREE, api, geometry);

  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(target);
  controls.update();

  document.getElementById('show-trail').addEventListener('change', (e) => {
    if (trail) trail.visible = e.target.checked;
    draw();
  });

  let state = api.state();
  function draw() {
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    if (canvas.width !== Math.floor(width * renderer.getPixelRatio()) ||
        canvas.height !== Math.floor(height * renderer.getPixelRatio())) {
      renderer.setSize(width, height, false);
      camera.aspect = width / Math.max(1, height);
      camera.updateProjectionMatrix();
    }
    body.quaternion.copy(quat(state.q));
    if (axisB) axisGroup.quaternion.setFromUnitVectors(axis0, axisB.clone().applyQuaternion(body.quaternion));
    if (bearings) {
      if (arrows.R_A_s) arrows.R_A_s.position.copy(bearings[0]).applyQuaternion(axisGroup.quaternion);
      if (arrows.R_B_s) arrows.R_B_s.position.copy(bearings[1]).applyQuaternion(axisGroup.quaternion);
    }
    for (const name of Object.keys(arrows)) setArrow(arrows[name], v3(state[name]).multiplyScalar(scaleOf(name)), size);
    wheels.forEach((w, k) => setArrow(w.arrow, v3(w.axis_b).multiplyScalar(state.rotor_h[k] * scaleOf('H_s')), size));
    movingBalls.forEach((ball, k) => ball.position.copy(v3(state.moving[k]).add(referenceO)));
    if (trail) trail.geometry.setDrawRange(0, trailCount(api, state.t));
    renderer.setViewport(0, 0, width, height);
    renderer.setScissorTest(false);
    renderer.clear();
    renderer.render(scene, camera);
    if (polhode) polhode.draw(renderer, state, width, height);
    api.drawn = true;
  }
  api.onTime((s) => { state = s; draw(); });
  /** Hides or shows a part of the drawing — 'body' (shape and point masses), 'axes' (space and body axes),
   * 'vectors' (the arrows and the point ω, H and M start from) or 'rotors' (the wheels, their axes and momenta) — and
   * redraws. */
  api.show = (part, visible) => {
    if (!parts[part]) throw new Error('eulerdyn view: no part ' + part + '; the parts are ' + Object.keys(parts).join(', '));
    for (const object of parts[part]) object.visible = Boolean(visible);
    draw();
  };
  controls.addEventListener('change', draw);
  window.addEventListener('resize', draw);
  api.redraw = draw;
  draw();
};

/** The body's shape in body axes from O (a group): its mesh, edges and a marker on its +x side. Every dimension is
 * drawn at least `min_drawn_thickness` (from the page's data: 5 % of the body's longest dimension), so that a thin
 * rod or disk shows as a solid, not a line hidden behind the axes. */
function makeShape(THREE, geometry) {
  const b = geometry.body || { kind: 'unknown' };
  const thick = (x) => Math.max(x || 0, b.min_drawn_thickness || 0);
  let g;
  let marker;
  switch (b.kind) {
    case 'thin_disk':
    case 'disk':
    case 'cylinder': {
      const r = thick(b.radius);
      const h = thick(b.kind === 'thin_disk' ? r / 25 : b.kind === 'disk' ? b.thickness : b.height);
      g = new THREE.CylinderGeometry(r, r, h, 64).rotateX(Math.PI / 2);
      marker = new THREE.BoxGeometry(r, r / 12, h * 1.06 + r / 200).translate(r / 2, 0, 0);
      break;
    }
    case 'thin_rod': {
      const l = b.length;
      const r = thick(l / 30) / 2;
      g = new THREE.CylinderGeometry(r, r, l, 24).rotateZ(Math.PI / 2);
      marker = new THREE.SphereGeometry(1.4 * r, 16, 8).translate(l / 2, 0, 0);
      break;
    }
    case 'sphere': {
      g = new THREE.SphereGeometry(b.radius, 48, 24);
      marker = new THREE.TorusGeometry(b.radius * 1.005, b.radius / 40, 8, 64).rotateX(Math.PI / 2);
      break;
    }
    case 'box':
    case 'inertia_box': {
      const s = b.size.map(thick);
      g = new THREE.BoxGeometry(s[0], s[1], s[2]);
      marker = new THREE.BoxGeometry(s[0] * 0.02 + 1e-6, s[1] * 0.6, s[2] * 0.6).translate(s[0] / 2, 0, 0);
      break;
    }
    default:
      g = new THREE.BoxGeometry(1, 1, 1);
      marker = new THREE.BoxGeometry(0.02, 0.6, 0.6).translate(0.5, 0, 0);
  }
  const group = new THREE.Group();
  // Translucent, so that the vectors drawn from O inside the body stay visible.
  const material = new THREE.MeshStandardMaterial({ color: 0x7d93b8, roughness: 0.55, metalness: 0.1,
    transparent: true, opacity: b.kind === 'unknown' ? 0.45 : 0.72, depthWrite: false });
  group.add(new THREE.Mesh(g, material));
  group.add(new THREE.LineSegments(new THREE.EdgesGeometry(g, 25), new THREE.LineBasicMaterial({ color: 0x40506e })));
  group.add(new THREE.Mesh(marker, new THREE.MeshStandardMaterial({ color: 0xf0c419, roughness: 0.5 })));
  if (b.kind === 'inertia_box' && b.axes_b) {
    const [e1, e2, e3] = b.axes_b.map((a) => new THREE.Vector3(a[0], a[1], a[2]));
    group.quaternion.setFromRotationMatrix(new THREE.Matrix4().makeBasis(e1, e2, e3));
  }
  if (b.center) group.position.set(b.center[0], b.center[1], b.center[2]);
  return group;
}

/** The colour of the wheels, their axes and their momentum arrows. */
const WHEEL_COLOR = 0x6a3d9a;

/** The wheels of the body (the page's rotors, those with an `_h` column), in body axes from O: for each, `wheel` (a
 * group: a disc of radius 0.14 body sizes across the spin axis at the wheel's centre, and the axis, a line 1.2 body
 * sizes long through it) and `arrow` (from the centre; set to h along the axis when drawn), with its `name` and
 * `axis_b`. */
function makeWheels(THREE, geometry, api, size) {
  const byName = Object.fromEntries((geometry.rotors || []).map((r) => [r.name, r]));
  return api.rotor_names.map((name) => {
    const r = byName[name];
    const axis = new THREE.Vector3(...r.axis_b);
    const at = new THREE.Vector3(...r.at);
    const wheel = new THREE.Group();
    const disc = new THREE.Mesh(new THREE.CylinderGeometry(0.14 * size, 0.14 * size, 0.04 * size, 40),
      new THREE.MeshStandardMaterial({ color: WHEEL_COLOR, roughness: 0.45, metalness: 0.3, transparent: true,
        opacity: 0.8 }));
    disc.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), axis);
    disc.position.copy(at);
    const ends = [at.clone().addScaledVector(axis, -0.6 * size), at.clone().addScaledVector(axis, 0.6 * size)];
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(ends),
      new THREE.LineBasicMaterial({ color: WHEEL_COLOR }));
    wheel.add(disc, line);
    wheel.name = 'rotor ' + name;
    const arrow = new THREE.ArrowHelper(axis.clone(), at.clone(), 1, WHEEL_COLOR);
    arrow.name = 'rotor momentum ' + name;
    return { name, axis_b: r.axis_b, at: r.at, wheel, arrow };
  });
}

/** Three axis lines from `origin`, of `length`, coloured x red, y green, z blue (lighter by `strength` < 1), with
 * labels. */
function axesLines(THREE, length, origin, strength, labels) {
  const group = new THREE.Group();
  const colors = [0xdd3333, 0x22aa22, 0x3366cc];
  for (let k = 0; k < 3; k++) {
    const dir = new THREE.Vector3();
    dir.setComponent(k, length);
    const color = new THREE.Color(colors[k]).lerp(new THREE.Color(0xffffff), 1 - strength);
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([origin.clone(), origin.clone().add(dir)]),
      new THREE.LineBasicMaterial({ color }));
    group.add(line);
    const label = textSprite(THREE, labels[k], '#' + color.getHexString(), length * 0.09);
    label.position.copy(origin.clone().add(dir.multiplyScalar(1.07)));
    group.add(label);
  }
  return group;
}

/** A text label facing the camera, `height` tall, drawn on a canvas (no font file). */
function textSprite(THREE, text, color, height) {
  const canvas = document.createElement('canvas');
  canvas.width = 128;
  canvas.height = 64;
  const ctx = canvas.getContext('2d');
  ctx.font = 'bold 40px sans-serif';
  ctx.fillStyle = color;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText(text, 64, 32);
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(canvas), depthTest: false }));
  sprite.scale.set(height * 2, height, 1);
  return sprite;
}

/** The fixed axis (a line through O) and the bearings (rings on it), added to `scene` (a group) where they are at
 * t = 0; returns the bearings' positions then, or null. */
function addAxisAndBearings(THREE, scene, geometry, q0, size) {
  if (!geometry.axis_b) return null;
  const u = new THREE.Vector3(...geometry.axis_b).applyQuaternion(q0).normalize();
  const reach = Math.max(2 * size, ...(geometry.bearings || []).map((a) => 1.3 * Math.abs(a)));
  const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([u.clone().multiplyScalar(-reach), u.clone().multiplyScalar(reach)]),
    new THREE.LineDashedMaterial({ color: 0x222222, dashSize: size / 10, gapSize: size / 20 }));
  line.computeLineDistances();
  scene.add(line);
  if (!geometry.bearings) return null;
  const along = new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 0, 1), u);
  return geometry.bearings.map((a, k) => {
    const at = u.clone().multiplyScalar(a);
    const ring = new THREE.Mesh(new THREE.TorusGeometry(size * 0.12, size * 0.035, 12, 40),
      new THREE.MeshStandardMaterial({ color: 0x555a66, roughness: 0.35, metalness: 0.5 }));
    ring.quaternion.copy(along);
    ring.position.copy(at);
    scene.add(ring);
    const label = textSprite(THREE, k === 0 ? 'A' : 'B', '#333844', size * 0.12);
    label.position.copy(at.clone().add(new THREE.Vector3(0, 0, size * 0.22)));
    scene.add(label);
    return at;
  });
}

/** Points of the body in body axes from O, to keep the vectors clear of: the center of the shape's bounding box
 * and points along its 12 edges (the body group is not turned yet when this is called). */
function bodySamples(THREE, shape) {
  const box = new THREE.Box3().setFromObject(shape);
  const corner = (k) => new THREE.Vector3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y,
    k & 4 ? box.max.z : box.min.z);
  const points = [box.getCenter(new THREE.Vector3())];
  for (let a = 0; a < 8; a++) {
    for (const bit of [1, 2, 4]) {
      if (a & bit) continue;
      for (let s = 0; s <= 4; s++) points.push(corner(a).lerp(corner(a | bit), s / 4));
    }
  }
  return points;
}

/** The point ω, H and M are drawn from: beside the body, not at O. Candidates: the 20 directions from O to the
 * edges' midpoints and the corners of a cube about O (not along the space axes, whose lines are drawn), at 1.2 body
 * sizes. Seen from the first view (`eye`: the camera's direction from its target; `screenUp` up), the arrows from each candidate
 * are compared with the body's `samples` at up to 400 kept rows: the candidate whose arrows lie over the body
 * (within 0.04 body sizes of it, on the screen) at the fewest rows, then the one farthest from the body on
 * average, then the highest. */
function vectorAnchor(THREE, api, samples, size, scaleOf, eye, screenUp) {
  const w = eye.clone().normalize();
  const right = screenUp.clone().cross(w).normalize();
  const up = w.clone().cross(right);
  const flat = (v) => [v.dot(right), v.dot(up)];
  const names = ['omega_s', 'H_s', 'M_s'].filter((n) => api.vectors.includes(n));
  const step = Math.max(1, Math.ceil(api.rows.length / 400));
  const rows = api.rows.filter((_, k) => k % step === 0);
  const bodies = rows.map((row) => {
    const q = new THREE.Quaternion(row.q[1], row.q[2], row.q[3], row.q[0]);
    return samples.map((s) => flat(s.clone().applyQuaternion(q)));
  });
  const tips = rows.map((row) => names.map((n) => flat(new THREE.Vector3(...row[n]).multiplyScalar(scaleOf(n)))));
  let choice = null;
  for (const x of [0, 1, -1]) {
    for (const y of [0, 1, -1]) {
      for (const z of [1, -1, 0]) {
        if (Math.abs(x) + Math.abs(y) + Math.abs(z) < 2) continue;
        const d = new THREE.Vector3(x, y, z).normalize();
        const a = flat(d.clone().multiplyScalar(1.2 * size));
        let over = 0;
        let sum = 0;
        rows.forEach((_, k) => {
          let near = Infinity;
          for (const tip of tips[k]) {
            const b = [a[0] + tip[0], a[1] + tip[1]];
            for (const p of bodies[k]) near = Math.min(near, segmentDistance(p, a, b));
          }
          if (near < 0.04 * size) over++;
          sum += Math.min(near, size);
        });
        const better = !choice || over < choice.over || (over === choice.over && sum > choice.sum + 1e-9 * size);
        if (better) choice = { d, over, sum };
      }
    }
  }
  return choice.d.clone().multiplyScalar(1.2 * size);
}

/** The distance in the plane from point p to the segment from a to b. */
function segmentDistance(p, a, b) {
  const ab = [b[0] - a[0], b[1] - a[1]];
  const len2 = ab[0] * ab[0] + ab[1] * ab[1];
  const s = len2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / len2)) : 0;
  return Math.hypot(p[0] - a[0] - s * ab[0], p[1] - a[1] - s * ab[1]);
}

/** Points `v` (space axes, already scaled) from the arrow's origin; hidden when v is 0. */
function setArrow(arrow, v, size) {
  const length = v.length();
  arrow.visible = length > 1e-12 * size;
  if (!arrow.visible) return;
  arrow.setDirection(v.clone().divideScalar(length));
  const head = Math.min(0.25 * length, 0.12 * size);
  arrow.setLength(length, head, 0.5 * head);
}

/** The trail of H's tip in space over the kept rows (H drawn from `origin`), drawn up to the current time. */
function makeTrail(THREE, api, scaleOf, origin) {
  if (!api.vectors.includes('H_s')) return null;
  const scale = scaleOf('H_s');
  const from = [origin.x, origin.y, origin.z];
  const points = new Float32Array(api.rows.length * 3);
  api.rows.forEach((row, k) => {
    for (let i = 0; i < 3; i++) points[3 * k + i] = from[i] + row.H_s[i] * scale;
  });
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(points, 3));
  return new THREE.Line(g, new THREE.LineBasicMaterial({ color: 0xd0309a, transparent: true, opacity: 0.55 }));
}

/** The number of kept rows at or before t, at least 1. */
function trailCount(api, t) {
  let lo = 0;
  let hi = api.rows.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (api.rows[mid].t <= t) lo = mid + 1; else hi = mid;
  }
  return Math.max(1, lo);
}

/** For free motion with a known inertia: the polhode inset — ω in principal axes on the energy ellipsoid
 * ω·I·ω = 2T of the first row — drawn into the lower right corner; null otherwise. */
function makePolhode(THREE, api, geometry) {
  if (geometry.motion !== 'free' || !geometry.inertia_p || !api.vectors.includes('omega_b')) return null;
  const inertia = geometry.inertia_p;
  const axes = geometry.axes_p_b;
  const toPrincipal = (w) => axes.map((a) => a[0] * w[0] + a[1] * w[1] + a[2] * w[2]);
  const path = api.rows.map((r) => toPrincipal(r.omega_b));
  const twoT = path[0].reduce((sum, w, i) => sum + inertia[i] * w * w, 0);
  if (!(twoT > 0) || inertia.some((i) => !(i > 0))) return null;
  const semi = inertia.map((i) => Math.sqrt(twoT / i));
  const reach = Math.max(...semi);
  const scene = new THREE.Scene();
  const ellipsoid = new THREE.Mesh(new THREE.SphereGeometry(1, 36, 18),
    new THREE.MeshBasicMaterial({ color: 0x8fa3c4, wireframe: true, transparent: true, opacity: 0.35 }));
  ellipsoid.scale.set(semi[0], semi[1], semi[2]);
  scene.add(ellipsoid);
  const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(path.map((w) => new THREE.Vector3(...w))),
    new THREE.LineBasicMaterial({ color: 0xe8a000 }));
  scene.add(line);
  const dot = new THREE.Mesh(new THREE.SphereGeometry(reach * 0.05, 16, 8), new THREE.MeshBasicMaterial({ color: 0xc0392b }));
  scene.add(dot);
  scene.add(axesLines(THREE, reach * 1.3, new THREE.Vector3(), 1.0, ['1', '2', '3']));
  const camera = new THREE.PerspectiveCamera(35, 1, reach / 100, reach * 100);
  camera.up.set(0, 0, 1);
  camera.position.set(2.6 * reach, -3.4 * reach, 2.2 * reach);
  camera.lookAt(0, 0, 0);
  const frame = document.getElementById('polhode-frame');
  if ((geometry.effects || []).length > 0) {
    frame.querySelector('.caption').textContent += '; with ' + geometry.effects.join(', ') +
      ' acting T changes, and the ellipsoid is the first row\'s';
  }
  const toggle = document.getElementById('show-polhode');
  document.getElementById('polhode-toggle').hidden = false;
  frame.hidden = false;
  toggle.addEventListener('change', () => { frame.hidden = !toggle.checked; api.redraw(); });
  return {
    draw(renderer, state, width, height) {
      if (!toggle.checked) return;
      dot.position.copy(new THREE.Vector3(...toPrincipal(state.omega_b)));
      const side = Math.floor(Math.min(240, width / 3, height / 2));
      frame.style.width = frame.style.height = side + 'px';
      renderer.setScissorTest(true);
      renderer.setScissor(width - side - 8, 8, side, side);
      renderer.setViewport(width - side - 8, 8, side, side);
      renderer.setClearColor(0xffffff, 1);
      renderer.clear();
      renderer.render(scene, camera);
      renderer.setClearColor(0xf4f5f7, 1);
      renderer.setScissorTest(false);
    },
  };
}

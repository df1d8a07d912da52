// eulerdyn view: the run's rows, the state between them, the clock and the controls. No three.js here: this part
// works (and window.eulerdyn answers) even where WebGL does not.
'use strict';
(function () {
  const data = JSON.parse(document.getElementById('eulerdyn-data').textContent);
  const columns = data.columns;
  const table = data.rows;
  const geometry = data.geometry || {};

  /** Indices of the columns `prefix_x, prefix_y, prefix_z` (or of the names given), or null if absent. */
  function indices(names) {
    const ix = names.map((n) => columns.indexOf(n));
    return ix.every((i) => i >= 0) ? ix : null;
  }
  const xyz = (p) => indices([p + '_x', p + '_y', p + '_z']);
  const vectorIndex = {
    omega_s: xyz('omega_s'),
    omega_b: xyz('omega_b'),
    H_s: xyz('H_s'),
    M_s: xyz('M_s'),
    R_A_s: xyz('R_A_s'),
    R_B_s: xyz('R_B_s'),
  };
  const qIndex = indices(['q_w', 'q_x', 'q_y', 'q_z']);
  // In orbit: nadir (from the sidecar's orbit) and the Earth's field (its columns in body axes), drawn as directions.
  const orbit = geometry.orbit || null;
  const fieldIndex = xyz('B_b');
  // The wheels ([[body.rotor]] in the sidecar's scene) whose axial momentum `<name>_h` the CSV has.
  const rotors = (geometry.rotors || []).map((r) => ({ ...r, index: columns.indexOf(r.name + '_h') }))
    .filter((r) => r.index >= 0);
  // The moving masses ([[body.moving_mass]]) whose position columns `<name>_x/_y/_z` the CSV has (from the reference
  // origin, body axes).
  const moving = (geometry.moving_masses || []).map((m) => ({ ...m, index: xyz(m.name) }))
    .filter((m) => m.index);
  const directionNames = [orbit && 'nadir_s', fieldIndex && 'field_s'].filter((n) => n);
  const vectorNames = Object.keys(vectorIndex).filter((k) => vectorIndex[k] !== null).concat(directionNames);

  /** v rotated by the unit quaternion q = [w, x, y, z] (body → space): v + 2w (u × v) + 2 u × (u × v). */
  function rotate(q, v) {
    const [w, x, y, z] = q;
    const c = [y * v[2] - z * v[1], z * v[0] - x * v[2], x * v[1] - y * v[0]];
    const cc = [y * c[2] - z * c[1], z * c[0] - x * c[2], x * c[1] - y * c[0]];
    return v.map((vi, i) => vi + 2 * w * c[i] + 2 * cc[i]);
  }

  /** The directions a row in orbit draws, in space axes: nadir on the circular orbit at the row's time,
   * −R_z(Ω) R_x(i) (cos u, sin u, 0) with u = u₀ + n t, and the field's direction B_b / |B_b| turned by q. */
  function directions(row, q, s) {
    if (orbit) {
      const u = orbit.arg_lat0 + orbit.mean_motion * s.t;
      const [ci, si, co, so] = [Math.cos(orbit.inclination), Math.sin(orbit.inclination), Math.cos(orbit.raan),
        Math.sin(orbit.raan)];
      const plane = [Math.cos(u), Math.sin(u) * ci, Math.sin(u) * si];
      s.nadir_s = [-(co * plane[0] - so * plane[1]), -(so * plane[0] + co * plane[1]), -plane[2]];
    }
    if (fieldIndex) {
      const b = fieldIndex.map((i) => row[i]);
      const norm = Math.hypot(b[0], b[1], b[2]);
      s.field_s = rotate(q, norm > 0 ? b.map((x) => x / norm) : b);
    }
  }

  /** The state of kept row k: its values exactly as embedded. */
  function rowState(k) {
    const row = table[k];
    const s = { t: row[0], q: qIndex.map((i) => row[i]) };
    for (const name of vectorNames) if (vectorIndex[name]) s[name] = vectorIndex[name].map((i) => row[i]);
    directions(row, s.q, s);
    s.rotor_h = rotors.map((r) => row[r.index]);
    s.moving = moving.map((m) => m.index.map((i) => row[i]));
    return s;
  }

  /** The largest k with t_k <= t (0 when t is before the first row). */
  function locate(t) {
    let lo = 0;
    let hi = table.length - 1;
    if (t >= table[hi][0]) return hi;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (table[mid][0] <= t) lo = mid; else hi = mid;
    }
    return lo;
  }

  /** a + s (b − a), componentwise. */
  function lerp(a, b, s) {
    return a.map((x, i) => x + s * (b[i] - x));
  }

  /** The attitude a fraction s of the way from qa to qb along the shorter great arc (slerp). */
  function slerp(qa, qb, s) {
    let dot = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3];
    const b = dot < 0 ? qb.map((x) => -x) : qb;
    dot = Math.abs(dot);
    if (dot > 0.9999999) {
      const q = lerp(qa, b, s);
      const n = Math.hypot(q[0], q[1], q[2], q[3]);
      return q.map((x) => x / n);
    }
    const theta = Math.acos(Math.min(1, dot));
    const wa = Math.sin((1 - s) * theta) / Math.sin(theta);
    const wb = Math.sin(s * theta) / Math.sin(theta);
    return qa.map((x, i) => wa * x + wb * b[i]);
  }

  const t0 = table[0][0];
  const tEnd = table[table.length - 1][0];

  /** The state at time t (clamped to the run): a kept row's values exactly at its time, else interpolated —
   * the attitude by slerp, the vectors linearly. */
  function stateAt(t) {
    const tc = Math.min(Math.max(t, t0), tEnd);
    const k = locate(tc);
    if (table[k][0] === tc || k === table.length - 1) return rowState(k);
    const a = rowState(k);
    const b = rowState(k + 1);
    const s = (tc - a.t) / (b.t - a.t);
    const out = { t: tc, q: slerp(a.q, b.q, s) };
    for (const name of vectorNames) out[name] = lerp(a[name], b[name], s);
    out.rotor_h = lerp(a.rotor_h, b.rotor_h, s);
    out.moving = a.moving.map((p, k) => lerp(p, b.moving[k], s));
    return out;
  }

  /** The run's typical rotation rate: the median of |ω| over the kept rows (rad/s). */
  function typicalRate() {
    const ix = vectorIndex.omega_s;
    const rates = table.map((row) => Math.hypot(row[ix[0]], row[ix[1]], row[ix[2]])).sort((a, b) => a - b);
    const n = rates.length;
    return n % 2 ? rates[(n - 1) / 2] : (rates[n / 2 - 1] + rates[n / 2]) / 2;
  }

  /** The default playback speed (simulated seconds per wall-clock second): about one turn per second at the
   * typical rate, 2π / median|ω| rounded to the nearest of 1, 2 and 5 × 10^k (in log scale); real time (1) when the
   * body does not turn. */
  function defaultSpeed(rate) {
    if (!(rate > 0) || !Number.isFinite(rate)) return 1;
    const exact = (2 * Math.PI) / rate;
    const decade = Math.pow(10, Math.floor(Math.log10(exact)));
    const ladder = [1, 2, 5, 10].map((m) => m * decade);
    return Number(ladder.reduce((a, b) => (Math.abs(Math.log(b / exact)) < Math.abs(Math.log(a / exact)) ? b : a))
      .toPrecision(1));
  }
  const typicalOmega = typicalRate();

  // The clock: the time shown, playing or not, and the speed (simulated seconds per wall-clock second).
  const clock = { t: t0, playing: false, speed: defaultSpeed(typicalOmega), last: null };
  const listeners = [];
  let current = stateAt(t0);

  function show() {
    current = stateAt(clock.t);
    for (const f of listeners) f(current, clock.t);
  }

  /** The time in the URL's fragment (`VIEW.html#t=0.44`), or null when it has none. */
  function fragmentTime() {
    const m = /(?:^#|&)t=([^&]*)/.exec(window.location.hash);
    const t = m ? Number(decodeURIComponent(m[1])) : NaN;
    return Number.isFinite(t) ? t : null;
  }

  /** Jumps to time t and pauses. */
  function setTime(t) {
    clock.playing = false;
    clock.t = Math.min(Math.max(Number(t), t0), tEnd);
    show();
  }

  const api = {
    rows: table.map((_, k) => rowState(k)),
    t_end: tEnd,
    t_start: t0,
    rows_in_run: data.rows_in_run,
    stride: data.stride,
    rows_note: data.rows_note,
    columns: columns,
    geometry: geometry,
    notes: data.notes,
    events: data.events || [],
    vectors: vectorNames,
    rotor_names: rotors.map((r) => r.name),
    moving_names: moving.map((m) => m.name),
    drawn: false,
    setTime: setTime,
    state: () => current,
    stateAt: stateAt,
    onTime: (f) => { listeners.push(f); f(current, clock.t); },
    play: () => { if (clock.t >= tEnd) clock.t = t0; clock.playing = true; clock.last = null; show(); },
    pause: () => { clock.playing = false; show(); },
    clock: clock,
    typical_rate: typicalOmega,
    default_speed: clock.speed,
    fragmentTime: fragmentTime,
  };
  window.eulerdyn = api;

  // Playback: advance the clock by the wall-clock time since the last frame times the speed.
  function frame(now) {
    if (clock.playing) {
      if (clock.last !== null) {
        clock.t = Math.min(tEnd, clock.t + ((now - clock.last) / 1000) * clock.speed);
        if (clock.t >= tEnd) clock.playing = false;
        show();
      }
      clock.last = now;
    } else {
      clock.last = null;
    }
    requestAnimationFrame(frame);
  }
  requestAnimationFrame(frame);

  // Open at the fragment's time (VIEW.html#t=0.44), and follow it when it is edited.
  const opened = fragmentTime();
  if (opened !== null) setTime(opened);
  window.addEventListener('hashchange', () => {
    const t = fragmentTime();
    if (t !== null && t !== clock.t) setTime(t);
  });

  window.eulerdynControls(api, data);
})();

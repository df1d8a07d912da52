// eulerdyn view: the controls (play/pause, time slider, speed, toggles), the readout of t and the vectors, the
// legend and the notes. Plain DOM; state.js calls eulerdynControls(api, data) once the rows are read.
'use strict';

/** What each vector is called, its colour in the scene and its CSV column prefix; shared with scene.js. */
window.eulerdynVectors = {
  omega_s: { label: 'ω (angular velocity)', color: '#e8a000', kind: 'omega' },
  H_s: { label: 'H (moment of momentum)', color: '#d0309a', kind: 'H' },
  M_s: { label: 'M (moment about the center)', color: '#1aa6b7', kind: 'M' },
  R_A_s: { label: 'R_A (bearing A on the body)', color: '#7a5230', kind: 'R' },
  R_B_s: { label: 'R_B (bearing B on the body)', color: '#a07850', kind: 'R' },
  nadir_s: { label: 'nadir (toward the Earth\'s centre)', color: '#2f7d32', kind: 'direction' },
  field_s: { label: 'the Earth\'s magnetic field B', color: '#6a3fb5', kind: 'direction' },
};

window.eulerdynControls = function (api, data) {
  const $ = (id) => document.getElementById(id);
  const units = (api.geometry && api.geometry.units) || {};
  const unitOf = (name) => (units[name + '_x'] || { omega_s: 'rad/s', H_s: 'kg*m^2/s', M_s: 'N*m' }[name] || 'N');
  const tUnit = units.t || 's';
  const fmt = (x) => (x === 0 ? '0' : Math.abs(x) >= 1e4 || Math.abs(x) < 1e-3 ? x.toExponential(3) : x.toPrecision(4));

  $('name').textContent = api.geometry.name || data.file || 'run';
  $('description').textContent = api.geometry.description || '';

  // Legend: colour, name, unit, and the longest arrow of each kind.
  const legend = ['<h2>Legend</h2><ul>'];
  legend.push('<li><span class="axis x"></span><span class="axis y"></span><span class="axis z"></span> space axes x, y, z (solid); body axes (thin, at C, turning with the body)</li>');
  for (const name of api.vectors) {
    const v = window.eulerdynVectors[name];
    if (!v) continue;
    if (v.kind === 'direction') {
      legend.push(`<li><span class="swatch" style="background:${v.color}"></span>${v.label}: its direction, from O</li>`);
      continue;
    }
    let longest = 0;
    for (const row of api.rows) longest = Math.max(longest, Math.hypot(...row[name]));
    // H shares its scale with the wheels' momenta.
    const withWheels = name === 'H_s' && api.rotor_names.length > 0;
    if (withWheels) for (const row of api.rows) for (const h of row.rotor_h) longest = Math.max(longest, Math.abs(h));
    legend.push(`<li><span class="swatch" style="background:${v.color}"></span>${v.label}, ${unitOf(name)}` +
      ` — arrow scaled so the longest${withWheels ? ' of H and the wheels\' h' : ''} (${fmt(longest)}) fits</li>`);
  }
  legend.push('<li><span class="swatch origin"></span>ω, H and M are drawn from the grey ball beside the body, not from' +
    ' O, so that they do not hide it (free vectors; M is the moment about O)</li>');
  if (api.vectors.includes('H_s')) legend.push('<li><span class="swatch trail"></span>trail of H\'s tip in space</li>');
  if (api.rotor_names.length) {
    legend.push(`<li><span class="swatch wheel"></span>wheels ${api.rotor_names.join(', ')}: each a disc on its spin` +
      ' axis, fixed in the body, and an arrow of its axial momentum h = J(a·ω + Ω) along the axis, at H\'s scale</li>');
  }
  if (api.geometry.body && api.geometry.body.drawn_thicker) {
    const said = api.geometry.body.drawn_thicker.replace(/&/g, '&amp;').replace(/</g, '&lt;');
    legend.push(`<li><span class="swatch body"></span>the body: ${said}</li>`);
  }
  legend.push('</ul>');
  $('legend').innerHTML = legend.join('');

  const notes = (data.notes || []).map((n) => `<li>${n.replace(/&/g, '&amp;').replace(/</g, '&lt;')}</li>`);
  $('notes').innerHTML = notes.length ? `<h2>Notes</h2><ul>${notes.join('')}</ul>` : '';
  $('notes').hidden = notes.length === 0;

  const listed = eventList($('events'), api.events || [], (t) => { api.setTime(t); keepFragment(); });

  const slider = $('time');
  const span = api.t_end - api.t_start;
  const toSlider = (t) => (span > 0 ? Math.round(((t - api.t_start) / span) * Number(slider.max)) : 0);
  // The URL's fragment follows the time shown when the user scrubs or pauses (#t=…), so that the address opens the
  // page at that time; written 0.2 s after the last change (browsers throttle frequent history updates).
  let fragmentTimer = null;
  function keepFragment() {
    clearTimeout(fragmentTimer);
    fragmentTimer = setTimeout(() => {
      const t = Number(api.clock.t.toPrecision(7));
      if (api.fragmentTime() !== t) history.replaceState(null, '', '#t=' + t);
    }, 200);
  }
  slider.addEventListener('input', () => {
    api.setTime(api.t_start + (span * Number(slider.value)) / Number(slider.max));
    keepFragment();
  });
  $('play').addEventListener('click', () => {
    if (api.clock.playing) { api.pause(); keepFragment(); } else api.play();
  });
  speedChoices($('speed'), api.default_speed);
  $('speed-rule').textContent = api.typical_rate > 0
    ? `${api.default_speed}× ≈ 1 turn/s (median |ω| ${fmt(api.typical_rate)} ${unitOf('omega_s')})`
    : 'the body does not turn: default 1× (real time)';
  $('speed').addEventListener('change', (e) => { api.clock.speed = Number(e.target.value); });
  document.addEventListener('keydown', (e) => {
    if (e.key === ' ' && e.target.tagName !== 'SELECT') { e.preventDefault(); $('play').click(); }
  });

  /** The readout: t, then each vector's components (space axes) and magnitude. */
  function readout(state) {
    const lines = [`<div class="t">t = ${fmt(state.t)} ${tUnit}</div><table>`];
    lines.push('<tr><th></th><th>x</th><th>y</th><th>z</th><th>|·|</th><th></th></tr>');
    for (const name of api.vectors) {
      const v = window.eulerdynVectors[name];
      if (!v) continue;
      const x = state[name];
      lines.push(`<tr><th style="color:${v.color}">${name}</th>${x.map((c) => `<td>${fmt(c)}</td>`).join('')}` +
        `<td>${fmt(Math.hypot(...x))}</td><td>${unitOf(name)}</td></tr>`);
    }
    const q = state.q.map(fmt).join(', ');
    lines.push(`</table><div class="q">q = (${q})</div>`);
    return lines.join('');
  }

  /** The speed menu: 1, 2 and 5 × 10^k from 1/1000 of the default (and 0.01×) up to 1000 × it (and 100×), real
   * time marked, the default selected. */
  function speedChoices(select, chosen) {
    const low = Math.min(0.01, chosen / 1000);
    const high = Math.max(100, chosen * 1000);
    const values = [];
    for (let e = Math.floor(Math.log10(low)); e <= Math.ceil(Math.log10(high)); e++) {
      for (const m of [1, 2, 5]) {
        const v = Number((m * Math.pow(10, e)).toPrecision(1));
        if (v >= low * 0.999 && v <= high * 1.001) values.push(v);
      }
    }
    select.innerHTML = values.map((v) => {
      const label = v + '×' + (v === 1 ? ' (real time)' : '') + (v === chosen ? ' (default)' : '');
      return `<option value="${v}"${v === chosen ? ' selected' : ''}>${label}</option>`;
    }).join('');
  }

  /** The located events as a table (a button with the name, t, the quantity and its value, the direction): a
   * click jumps to the event's time. Returns a function that marks the rows at the time shown. */
  function eventList(box, events, jump) {
    box.hidden = events.length === 0;
    if (!events.length) return () => {};
    const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;');
    const rows = events.map((e, k) => `<tr data-k="${k}"><td><button type="button" class="event" data-k="${k}"` +
      ` title="show t = ${e.t}">${esc(e.event)}</button></td><td>t = ${fmt(e.t)} ${tUnit}</td>` +
      `<td>${esc(e.when || 'value')} = ${fmt(e.value)}</td><td>${esc(e.direction)}</td></tr>`);
    box.innerHTML = `<h2>Events (${events.length}): click to show</h2><table>${rows.join('')}</table>`;
    box.addEventListener('click', (ev) => {
      const button = ev.target.closest('button.event');
      if (button) jump(events[Number(button.dataset.k)].t);
    });
    const trs = box.querySelectorAll('tr');
    return (t) => trs.forEach((tr, k) => tr.classList.toggle('current', events[k].t === t));
  }

  api.onTime((state, t) => {
    listed(t);
    $('readout').innerHTML = readout(state);
    $('clock').textContent = `t = ${fmt(t)} ${tUnit} of ${fmt(api.t_end)}`;
    slider.value = String(toSlider(t));
    $('play').textContent = api.clock.playing ? '❚❚' : '▶';
  });
};

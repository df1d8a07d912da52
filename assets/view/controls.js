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
    let longest = 0;
    for (const row of api.rows) longest = Math.max(longest, Math.hypot(...row[name]));
    legend.push(`<li><span class="swatch" style="background:${v.color}"></span>${v.label}, ${unitOf(name)}` +
      ` — arrow scaled so the longest (${fmt(longest)}) fits</li>`);
  }
  if (api.vectors.includes('H_s')) legend.push('<li><span class="swatch trail"></span>trail of H\'s tip in space</li>');
  legend.push('</ul>');
  $('legend').innerHTML = legend.join('');

  const notes = (data.notes || []).map((n) => `<li>${n.replace(/&/g, '&amp;').replace(/</g, '&lt;')}</li>`);
  $('notes').innerHTML = notes.length ? `<h2>Notes</h2><ul>${notes.join('')}</ul>` : '';
  $('notes').hidden = notes.length === 0;

  const slider = $('time');
  const span = api.t_end - api.t_start;
  const toSlider = (t) => (span > 0 ? Math.round(((t - api.t_start) / span) * Number(slider.max)) : 0);
  slider.addEventListener('input', () => api.setTime(api.t_start + (span * Number(slider.value)) / Number(slider.max)));
  $('play').addEventListener('click', () => (api.clock.playing ? api.pause() : api.play()));
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

  api.onTime((state, t) => {
    $('readout').innerHTML = readout(state);
    $('clock').textContent = `t = ${fmt(t)} ${tUnit} of ${fmt(api.t_end)}`;
    slider.value = String(toSlider(t));
    $('play').textContent = api.clock.playing ? '❚❚' : '▶';
  });
};

// eulerdyn view: imports three.js — kept in the page as text — from blob: URLs made here (no network request), then
// draws the scene. three.module.js imports './three.core.js' and OrbitControls imports 'three': both specifiers are
// pointed at the blob URLs before import.
'use strict';
(async function () {
  const text = (id) => document.getElementById(id).textContent;
  const blobUrl = (source) => URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
  /** `source` with every `from 'specifier'` pointed at `url`; an error if there was none. */
  function pointAt(source, specifier, url) {
    const from = "from '" + specifier + "'";
    if (!source.includes(from)) throw new Error('eulerdyn view: the embedded three.js has no ' + from);
    return source.split(from).join("from '" + url + "'");
  }
  try {
    const core = blobUrl(text('three-core'));
    const three = blobUrl(pointAt(text('three-module'), './three.core.js', core));
    const orbit = blobUrl(pointAt(text('three-orbit'), 'three', three));
    const THREE = await import(three);
    const { OrbitControls } = await import(orbit);
    window.eulerdynScene(THREE, OrbitControls, window.eulerdyn);
  } catch (e) {
    const box = document.getElementById('error');
    box.hidden = false;
    box.textContent = 'The 3D view could not start: ' + (e && e.message ? e.message : e) +
      '. The readout and window.eulerdyn still work.';
    console.error(e);
  }
})();

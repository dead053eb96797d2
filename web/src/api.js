// window.zomeify: a small scripting API over the page (documented in web/README.md). Every call
// returns a promise; failures reject with the same one-line message the page shows.
export function installApi(app, { ready, warmedUp, info, buildView = null, work = null }) {
  const api = {
    /** Resolves with {threaded, maxThreads, crossOriginIsolated} once the first model is shown. */
    ready,
    /** Resolves (with its milliseconds, or null) once the start-up warm-up run has finished. */
    warmedUp,
    info,
    /** A File (or {name, bytes: ArrayBuffer|Uint8Array}); {run: true} starts a run afterwards. */
    async load(file, options = {}) {
      const result = file instanceof Blob
        ? await app.loadFile(file, options)
        : await app.loadBytes(file.name, file.bytes instanceof ArrayBuffer ? file.bytes : file.bytes.slice().buffer, options);
      if (result.ok === false) throw new Error(result.error);
      return result;
    },
    async loadUrl(url, options = {}) {
      const result = await app.loadUrl(url, options);
      if (result.ok === false) throw new Error(result.error);
      return result;
    },
    /** Runs with RunOptions (web/src/protocol.js); resolves with the final progress. */
    run: (options) => app.run(options),
    /** A step on the model on screen ('improve', 'fewer', 'more', 'fix'); resolves with the run's end. */
    workOn: (kind) => work.step(kind),
    /** Chooses the spot of Fix here, as a click on the shape does (mesh units). */
    chooseSpot: (point) => work.setSpot(point),
    /** The spot chosen, or null. */
    spot: () => work.spot,
    /** Puts back the model before the last step. */
    undo: () => work.undo(),
    cancel: () => app.cancel(),
    /** A resolution set here is kept for the meshes loaded next (scripts choose; the page does not). */
    setOptions: (options) => app.controls.set({ ...options, pinned: options.resolution !== undefined }),
    options: () => app.controls.get(),
    /** Runs finished so far (a run started by a drop can be waited for with it). */
    runs: () => app.runCount,
    /** 'running' or 'idle'. */
    state: () => (app.running ? 'running' : 'idle'),
    progress: () => app.lastProgress,
    summary: () => app.bridge.summary(),
    /** The parts report; with kits (`"2x creator3, 1x basic"`) also what they lack (`missing`). */
    parts: (have) => app.bridge.parts(have),
    /** The page's address with the model in its fragment (#m=2.…). */
    shareLink: () => app.shareLink({ copy: false }),
    openLink: async (link) => {
      const result = await app.openLink(link);
      if (!result.ok) throw new Error(result.error);
      return result;
    },
    /** {name, bytes: Uint8Array} of an export: .vef .glb .obj .mtl .zome.json .csv */
    exportModel: (name, options) => app.bridge.exportModel(name, options),
    lastError: () => app.lastError,
    /** Fractions of the canvas in each strut colour (a pixel check of the rendering). */
    colourCoverage: () => app.viewer.colourCoverage(),
    fit: () => app.viewer.fit(),
    /** The mirror plane drawn in the view ({axis: 0..2, at} in Zome units), or null. */
    mirrorPlane: () => app.viewer.mirrorPlane,
    /** The camera: {position, target} (mesh units); tests check that a drag or a pinch moved it. */
    camera: () => ({ position: app.viewer.camera.position.toArray(), target: app.viewer.controls.target.toArray() }),
    /** The estimate the controls show (the core's answer for the resolution on the slider), or null. */
    estimate: () => app.controls.lastEstimate,
    /** The Build view: opens it (resolves with the plan: nodes, steps, figures, html) and shows step k (0-based). */
    openBuildView: () => buildView.open(),
    buildStep: (k) => buildView.show(k),
  };
  window.zomeify = api;
  return api;
}

// The message protocol between the page (bridge.js) and the core worker (worker/core_worker.js).
// Every request is {id, type, ...fields}; the worker answers each with exactly one
// {id, type: 'reply', ok: true, result} or {id, type: 'reply', ok: false, error}. Events carry no id.
// Typed with JSDoc; web/README.md has the same table for readers.

/** Requests (page → worker). */
export const Request = Object.freeze({
  INIT: 'init',           // {wasmBase, threaded}            → {threaded, maxThreads, defaults, schema}
  LOAD: 'load',           // {name, bytes: ArrayBuffer, thicken?} → {kind: 'mesh'|'model', report?}
  OPEN_LINK: 'openLink',  // {link}                          → {kind: 'model'}
  ESTIMATE: 'estimate',   // {resolution, target, kits}      → {nodes, struts, genus, surface_genus, kept, advice,
                          //                                    advice_resolution, size_mm, kits, kit_plan, kit_plan_low}
                          //                                    (kits: false leaves out the kit fields and their quick pass)
  ESTIMATE_SIZE: 'estimateSize', // {sizeCm, target}        → estimate's fields + {size_cm, b1} (as run --size-cm)
  KIT_CHECK: 'kitCheck',  // {have, balls}                   → {fits, text, owned, missing{B0..R2, balls}, budget}
  FIT_KITS: 'fitKits',    // {have, maxResolution, shrink}   → {possible, resolution, target_nodes, size_cm, message, ...}
  AUTO_RESOLUTION: 'autoResolution', // {}                   → estimate's fields + the core's choice {resolution, target_nodes, message, ...}
  RUN: 'run',             // {options: RunOptions}           → final Progress (after the run ends)
  CANCEL: 'cancel',       // {}                              → {}   (the run's reply follows when it stops)
  SNAPSHOT: 'snapshot',   // {}                              → Snapshot
  SURFACE: 'surface',     // {}                              → {positions, triangles} | null
  PARTS: 'parts',         // {have?}                         → parts report (+ missing with the kits in have) (see core/parts/parts_report.h)
  BUILD_PLAN: 'buildPlan', // {up}                          → plan (core/assembly/plan_report.h plan_json) + {html}
  EXPORT: 'export',       // {name, options?: {vefFaces, objUnits}} → {name, bytes: Uint8Array}
  LINK: 'link',           // {}                              → {link: 'm=2.…'}
  SUMMARY: 'summary',     // {}                              → Summary
  WARM_UP: 'warmUp',      // {}                              → {ms}  (a short hidden run; see core_worker.js)
});

/** Events (worker → page). */
export const Event = Object.freeze({
  PROGRESS: 'progress',   // {progress: Progress}            several times a second during a run
  SNAPSHOT: 'snapshot',   // {snapshot: Snapshot}            whenever the model changed (≥ 2/s in a run)
  FATAL: 'fatal',         // {error}                         the worker cannot continue
  CHECKPOINT: 'checkpoint', // {name, bytes}                 single-threaded run: the model as .zome.json, every second
});

/**
 * @typedef {object} RunOptions
 * @property {number} [resolution]   cells along the longest side for Z0 (bounds: the core's schema)
 * @property {number} [seconds]      annealing time budget
 * @property {number} [target_nodes] N_target; 0 = the node count of Z0
 * @property {number} [size_cm]      > 0: the built longest side in cm instead of the resolution (as run --size-cm)
 * @property {number} [threads]      annealing threads (clamped to maxThreads)
 * @property {number} [seed]
 * @property {'auto'|'off'} [mirror] 'auto': a mirror-symmetric model when the shape is (core/pipeline/mirror_choice.h)
 * @property {{dist?: number, orient?: number, fair?: number, complex?: number}} [weights]
 */

/**
 * @typedef {object} Progress
 * @property {'idle'|'initial'|'annealing'|'done'|'cancelled'|'failed'} state
 * @property {number} seconds @property {number} budget_seconds @property {number} temperature
 * @property {number} energy @property {number} best_energy @property {number} proposals
 * @property {number} commits @property {number} nodes @property {number} struts
 * @property {number} threads @property {boolean} annealer @property {string} note @property {string} error
 */

/**
 * @typedef {object} Snapshot
 * @property {number} version       changes whenever the model changes
 * @property {Float32Array} positions   xyz per ball, Zome units (b0 = 1)
 * @property {Uint32Array} struts       node index pairs
 * @property {Uint8Array} kinds         per strut 0..8 = B0 B1 B2 Y0 Y1 Y2 R0 R1 R2 (255: not a Zome vector)
 * @property {Uint32Array} triangles    faces as triangles (node indices)
 * @property {number} scale             Zome units → mesh units
 * @property {number[]} translation
 */

/**
 * @typedef {object} Summary
 * @property {string} source  'none' | 'file' | 'link' | 'run'
 * @property {number} balls @property {number} struts @property {number} faces
 * @property {Object<string, number>} by_kind   e.g. {B0: 12, Y1: 30}
 * @property {boolean|null} valid   closed 2-manifold obeying the Zome rules (null: the model has no faces)
 * @property {number} [genus] @property {object} stats @property {string} surface
 */

export const KIND_NAMES = ['B0', 'B1', 'B2', 'Y0', 'Y1', 'Y2', 'R0', 'R1', 'R2'];

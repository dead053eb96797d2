// The kits a person owns and the built size, as the page's form holds them: pure text and checks
// (no DOM) so web/tests/ can check them. The core decides what fits (core/parts/kit_fit.h); these
// only turn its answers into sentences and the form into the `--have` syntax the core parses.

/** The standard kits, in the order the picker shows them (ids as core/parts/kits.cpp). */
export const KITS = [
  { id: 'basic', name: 'Basic' },
  { id: 'creator1', name: 'Creator 1' },
  { id: 'creator3', name: 'Creator 3' },
  { id: 'workshop', name: 'Workshop' },
];
export const MAX_KITS = 99;
// The sizes the core accepts (core/assembly/real_size.cpp: 3 to 256 b1 struts along the longest side).
export const SIZE_CM = { min: 25, max: 1900 };

/**
 * {have: 'creator3, 2x basic', error: ''} from {kitId: count}: every count a whole number 0..99;
 * otherwise `error` names the kit and `have` is ''.
 */
export function haveText(counts) {
  const items = [];
  for (const { id, name } of KITS) {
    const raw = counts[id];
    if (raw === undefined || raw === '' || raw === null) continue;
    const n = Number(raw);
    if (!Number.isInteger(n) || n < 0 || n > MAX_KITS) {
      return { have: '', error: `${name}: the number of kits must be a whole number from 0 to ${MAX_KITS}` };
    }
    if (n > 0) items.push(`${n}x ${id}`);
  }
  return { have: items.join(', '), error: '' };
}

/** "2x basic, 1x creator3" (haveText's form) as the core names it: "2 x Basic + 1 x Creator 3". */
export function ownedName(have) {
  return have.split(',').map((item) => item.trim()).filter(Boolean).map((item) => {
    const [, n, id] = item.match(/^(\d+)x (\w+)$/) || [];
    const kit = KITS.find((k) => k.id === id);
    return kit ? `${n} x ${kit.name}` : item;
  }).join(' + ');
}

/** {cm, error}: the size field's value checked against the core's range, with a sentence if wrong. */
export function checkSize(value) {
  const cm = Number(value);
  if (value === '' || !Number.isFinite(cm) || cm < SIZE_CM.min || cm > SIZE_CM.max) {
    return { cm: 0, error: `The size must be a number of centimetres from ${SIZE_CM.min} to ${SIZE_CM.max}.` };
  }
  return { cm, error: '' };
}

/** Before a run: the core's kit check of the estimate (Session::kit_check) as a sentence. */
export function estimateFitText(check, balls) {
  const what = `a model of about ${balls} balls`;
  return check.fits
    ? `With your kits (${check.owned}): ${what} typically fits; the result is checked after the run.`
    : `With your kits (${check.owned}): ${what} typically does not fit (${check.text}). Try "Fit my kits".`;
}

/** The parts missing in a counts object {B0: 3, ..., balls: 2} ('' when none). */
export function missingText(missing) {
  if (!missing) return '';
  const items = Object.entries(missing).filter(([k, n]) => k !== 'balls' && n > 0).map(([k, n]) => `${n} ${k}`);
  if (missing.balls > 0) items.push(`${missing.balls} balls`);
  return items.join(', ');
}

/** After a run: the parts report with `missing` (Session::parts(have)) as a sentence. */
export function resultFitText(report, owned) {
  if (!report?.missing) return '';
  const missing = missingText(report.missing);
  return missing
    ? `Your kits (${owned}) do not hold this model: missing ${missing}. "Fit my kits" again plans a smaller one.`
    : `Your kits (${owned}) hold every part of this model.`;
}

/**
 * The fit plan (Session::fit_kits) as the one sentence beside the button. It names no size: the
 * estimate line above gives the model's size once. `sizeLimit` ({cm, resolution}) is the built size
 * the user asked; when the plan stopped at it, the sentence says the size decided, not the kits.
 */
export function fitPlanText(plan, sizeLimit = null) {
  if (!plan.possible) return `Cannot fit your kits (${plan.owned}): ${plan.message}.`;
  const bySize = sizeLimit && sizeLimit.resolution > 0 && plan.resolution >= sizeLimit.resolution;
  const why = bySize
    ? ` Your size limit (at most ${Math.round(sizeLimit.cm)} cm) decided this, not the kits: they hold a larger model.`
    : '';
  return `Fit my kits (${plan.owned}): ${plan.resolution} cells, target ${plan.target_nodes} balls, ` +
    'kept below what the kits hold as the strut mix varies.' + why +
    (plan.genus_kept ? '' : ' No size within your kits keeps the shape\'s holes.') +
    ' Press Run: the result is checked against your kits.';
}

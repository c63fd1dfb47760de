// DOM helpers. The DOM is built with createElement and textContent only: no user or URL value
// is ever parsed as HTML or run as code.

export const $ = (id) => document.getElementById(id);

/** An element with properties (`text`, `class`, `on<event>`, attributes) and children. */
export const el = (tag, props = {}, ...kids) => {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'text') e.textContent = v;
    else if (k === 'class') e.className = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (v !== undefined && v !== null && v !== false) e.setAttribute(k, v === true ? '' : String(v));
  }
  for (const c of kids) if (c !== null && c !== undefined) e.append(c);
  return e;
};

// DOM writes that skip a value the node already has: an unchanged text, attribute or hidden
// flag then costs no style recalculation, layout or repaint.
export const setText = (node, text) => { if (node.textContent !== text) node.textContent = text; };
export const setAttr = (node, name, value) => { if (node.getAttribute(name) !== value) node.setAttribute(name, value); };
export const setHidden = (node, hidden) => { if (node.hidden !== hidden) node.hidden = hidden; };

/** The message of an error (or the value as text). */
export const errText = (e) => (e && typeof e === 'object' && 'message' in e ? String(e.message) : String(e));

/**
 * `fn()` in a task after the next frame (its pixels are committed by then): work that must not
 * delay the frame that shows an input (a classroom panel, the history entry: pushState costs
 * 6–20 ms on a long hash). Two hops: the task the frame's callbacks post first would run before
 * those posted after it in the same frame (what measures "painted"); the second hop queues `fn`
 * behind them. A hidden page has no frames: then after 200 ms.
 */
export function afterPaint(fn) {
  let started = false;
  const go = () => {
    if (started) return;
    started = true;
    clearTimeout(timer);
    setTimeout(() => setTimeout(fn, 0), 0);
  };
  const timer = setTimeout(go, 200);
  requestAnimationFrame(go);
}

// Where an input event's time went, from a Chromium trace (a measurement helper, not a test;
// bench/page-latency.mjs --event-timing --trace uses it). Chromium's Event Timing duration runs
// from the event's hardware timestamp to the presentation of the next frame painted after its
// handlers; the trace's own EventTiming record of that event gives the window, and the events in
// it say what filled it:
//   handlers  when this event's handlers ran (after the event's timestamp) and when the commit of
//             the frame after them finished; input tasks: the page thread's input tasks in the
//             window (every event of the input: pointerdown, mouseup, click, keydown, keypress,
//             input, change …), ms;
//   frame     each BeginMainFrame of the page thread in the window: its start after the event
//             (the wait for the next vsync before it) and its time, split into style, layout,
//             paint (with the size of each painted layer's area), layerize, commit (the page
//             thread waits for the compositor thread to take the layer tree: longer when more
//             changed) and the animation-frame callbacks;
//   draw      the display compositor's draw and swap of the frame presented at the window's end
//             (the software renderer of headless Chromium: its time follows the damaged area,
//             given as x,y w×h of the viewport);
//   other     the page thread's other tasks in the window over 0.3 ms (timers, messages …).
// Needs the categories startTrace() records.

const CATEGORIES = 'devtools.timeline,disabled-by-default-devtools.timeline,cc,benchmark,viz';

/** Starts a trace of `page` (playwright); `stop()` ends it and resolves to its events. */
export async function startTrace(page) {
  const cdp = await page.context().newCDPSession(page);
  const events = [];
  cdp.on('Tracing.dataCollected', (e) => events.push(...e.value));
  const done = new Promise((r) => cdp.on('Tracing.tracingComplete', r));
  await cdp.send('Tracing.start', { categories: CATEGORIES, transferMode: 'ReportEvents' });
  return {
    async stop() {
      await cdp.send('Tracing.end');
      await done;
      await cdp.detach();
      return events;
    },
  };
}

const ms = (us) => (us / 1000).toFixed(1);

/** One line saying where the time of the event `entry` ({ name: its type, start: its
 *  timestamp, as the page's PerformanceEventTiming gives them }) went; '' when the trace lacks it. */
export function explain(events, entry) {
  if (!entry) return '';
  const rec = events.find((e) => e.name === 'EventTiming' && e.ph === 'b' && e.args && e.args.data && e.args.data.type === entry.name && Math.abs(e.args.data.timeStamp - entry.start) < 0.2);
  if (!rec) return '(not in the trace)';
  const d = rec.args.data;
  const a = rec.ts, z = rec.ts + d.duration * 1000;
  const mainOf = (e) => e.pid === rec.pid && e.tid === rec.tid && e.ph === 'X';
  const inWin = (e) => e.ts < z && e.ts + (e.dur || 0) > a;
  const main = events.filter((e) => mainOf(e) && inWin(e));
  const within = (t) => main.filter((e) => e.ts >= t.ts && e.ts + e.dur <= t.ts + t.dur && e !== t);
  // the page thread's top-level tasks
  const tasks = main.filter((e) => e.name === 'RunTask').sort((x, y) => x.ts - y.ts);
  const top = [];
  let end = 0;
  for (const t of tasks) if (t.ts >= end) { top.push(t); end = t.ts + t.dur; }
  let input = 0;
  const frames = [];
  const other = [];
  for (const t of top) {
    const kids = within(t);
    const bmf = kids.find((k) => k.name === 'ProxyMain::BeginMainFrame');
    if (bmf) {
      const sum = (n) => kids.filter((k) => k.name === n).reduce((s, k) => s + k.dur, 0);
      const clips = kids.filter((k) => k.name === 'Paint' && k.args && k.args.data && Array.isArray(k.args.data.clip)).map((k) => {
        const c = k.args.data.clip;
        return `${Math.round(Math.abs(c[2] - c[0]))}×${Math.round(Math.abs(c[5] - c[1]))}`;
      });
      frames.push(`frame at +${ms(bmf.ts - a)}: ${ms(bmf.dur)} (style ${ms(sum('UpdateLayoutTree'))}, layout ${ms(sum('Layout'))}, rAF ${ms(sum('FireAnimationFrame'))}, paint ${ms(sum('Paint'))}${clips.length ? ' [' + clips.join(' ') + ']' : ''}, layerize ${ms(sum('Layerize'))}, commit ${ms(sum('Commit'))})`);
    } else if (kids.some((k) => k.name === 'WidgetBaseInputHandler::OnHandleInputEvent' || k.name === 'EventDispatch')) {
      input += t.dur;
    } else if (t.dur > 300) {
      const k = kids.find((x) => ['TimerFire', 'HandlePostMessage', 'FireIdleCallback', 'FunctionCall', 'EventDispatch', 'ParseHTML'].includes(x.name));
      other.push(`${k ? k.name + (k.args && k.args.data && k.args.data.functionName ? ' ' + k.args.data.functionName : '') : 'task'} +${ms(t.ts - a)} ${ms(t.dur)}`);
    }
  }
  const draws = events.filter((e) => e.name === 'Display::DrawAndSwap' && e.ph === 'X' && e.ts >= a && e.ts + e.dur <= z + 500);
  const draw = draws.length ? draws[draws.length - 1] : null;
  // the display's damaged rectangle in that draw (x,y w×h in the viewport)
  const dmg = draw ? events.find((e) => e.name === 'DirectRenderer::DrawFrame ProcessForOverlays' && e.pid === draw.pid && e.ts >= draw.ts && e.ts <= draw.ts + draw.dur) : null;
  const rel = (t) => (t - d.timeStamp).toFixed(1);
  return `its handlers at +${rel(d.processingStart)}–${rel(d.processingEnd)}, commit done +${rel(d.commitFinishTime)}; input tasks ${ms(input)}; ${frames.join('; ') || 'no frame'}; draw ${draw ? `at +${ms(draw.ts - a)}: ${ms(draw.dur)}${dmg ? ' [damage ' + dmg.args.root_damage_rect + ']' : ''}` : '–'}${other.length ? '; other: ' + other.join(', ') : ''}`;
}

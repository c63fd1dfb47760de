// Writes the index.html of the offline classroom bundle (scripts/bundle.sh): example
// embeddings of pidlab.html in instructor mode, each an <iframe> whose hash carries the state
// (url.js encodeHash) and the instructor parameters (README, "Instructor mode"), and a small
// demonstration of the postMessage API. Usage: node scripts/bundle-index.mjs <out.html>
import { writeFileSync } from 'node:fs';
import * as S from '../www/state.js';
import * as U from '../www/url.js';

const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

const ifoptd = { family: 'ifoptd', k: 1, tau: 1, theta: 0.5 };
const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const base = (over) => ({ ...S.defaultState(), target: null, ...over });

export const EXAMPLES = [
  {
    title: 'Predict Ms before you look',
    text: 'Students move λ of Shamsuzzoha & Lee’s IMC-PID on an integrating plant and predict the peak sensitivity Ms and Mt; the numbers are hidden until they press “Reveal”.',
    hash: U.encodeHash(base({ plant: ifoptd, method: 'shamsuzzoha_lee', params: { lambda: 0.6 }, show: ['mp-lambda'] }), true) + '&panels=servo,load,nyquist,bode&hide=ms,mt',
  },
  {
    title: 'The robustness–performance trade-off',
    text: 'IAE and TV against Ms as λ is swept; the current design is the black dot. The plant is fixed (its sliders are locked).',
    hash: U.encodeHash(base({ plant: ifoptd, method: 'shamsuzzoha_lee', params: { lambda: 0.8 }, show: ['mp-lambda', 'fp-theta'] }), true) + '&panels=servo,tradeoff&lock=fp-theta',
  },
  {
    title: 'Why a loop fails: model error',
    text: 'Praveen Kumar & Narayana’s rule on the boiler model; the dead-time and gain sliders perturb the true plant and the Nyquist plot shows the envelope of L.',
    hash: U.encodeHash(base({ plant: boiler, method: 'praveen_kumar', params: { lambda: 0.5 }, pert: { k: 10, tau: 0, zero: 0, theta: 30 }, show: ['pt-k', 'pt-theta'] }), true) + '&panels=servo,nyquist',
  },
  {
    title: 'Auf Deutsch',
    text: 'The same page with German labels (lang=de; add a language as a table in www/i18n.js).',
    hash: U.encodeHash(base({ plant: ifoptd, method: 'shamsuzzoha_lee', params: { lambda: 0.6 }, show: ['mp-lambda'] }), true) + '&panels=servo,bode&lang=de',
  },
];

// The API demonstration: the host asks for the design and shows the student's Ms as it changes.
// (Opened from disk the page's origin is "null", hence api=*; on a web server name the origin.)
const apiHash = U.encodeHash(base({ plant: ifoptd, method: 'shamsuzzoha_lee', params: { lambda: 0.6 }, show: ['mp-lambda'] }), true) + '&panels=servo&api=*';
const apiScript = `
const f = document.getElementById('api-frame');
const out = document.getElementById('api-out');
addEventListener('message', (e) => {
  if (e.source !== f.contentWindow) return;
  const m = e.data;
  if (!m || typeof m !== 'object') return;
  if (m.type === 'pidlab:ready') f.contentWindow.postMessage({ type: 'pidlab:get', id: 1 }, '*');
  if (m.type === 'pidlab:design' || m.type === 'pidlab:change') {
    out.textContent = (m.type === 'pidlab:change' ? 'changed by the ' + m.source + ': ' : 'design: ') + 'λ = ' + m.state.params.lambda + ', Ms = ' + (m.metrics.ms === null ? '–' : m.metrics.ms.toFixed(3));
  }
});
document.getElementById('api-set').addEventListener('click', () => f.contentWindow.postMessage({ type: 'pidlab:set', id: 2, state: { params: { lambda: 1.5 } } }, '*'));
`;

const frames = EXAMPLES.map((e, i) => `
<section>
  <h2>${esc(e.title)}</h2>
  <p>${esc(e.text)}</p>
  <iframe id="ex${i}" src="pidlab.html${esc(e.hash)}" title="pidlab: ${esc(e.title)}" width="100%" height="760" style="border:0" loading="lazy"></iframe>
  <p><small>Embed code: <code>${esc('<iframe src="pidlab.html' + e.hash + '" width="100%" height="760" style="border:0"></iframe>')}</code></small></p>
</section>`).join('\n');

const html = `<!doctype html>
<html lang="en">
<head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>pidlab for the classroom: example embeddings</title>
<style>body{font-family:system-ui,sans-serif;max-width:70rem;margin:0 auto;padding:1rem;line-height:1.4} code{word-break:break-all} section{margin-bottom:2rem}</style>
</head>
<body>
<h1>pidlab for the classroom</h1>
<p>Open these pages offline: everything is in <code>pidlab.html</code> (the module and the page in one file) and this file. Each example is an <code>&lt;iframe&gt;</code> of <code>pidlab.html</code> whose URL hash sets the state and the instructor parameters (see the README, “Instructor mode”).</p>
${frames}
<section>
  <h2>The postMessage API</h2>
  <p>This page reads the student's design from the embedded pidlab and sets λ.</p>
  <p><button type="button" id="api-set">Set λ = 1.5</button> <output id="api-out" aria-live="polite">waiting for pidlab…</output></p>
  <iframe id="api-frame" src="pidlab.html${esc(apiHash)}" title="pidlab with the postMessage API" width="100%" height="600" style="border:0"></iframe>
</section>
<script>${apiScript}</script>
</body>
</html>
`;

const out = process.argv[2];
if (!out) {
  console.error('usage: node scripts/bundle-index.mjs <out.html>');
  process.exit(2);
}
writeFileSync(out, html);

// The page's language for embedded classroom pages (#lang=de): a table of label texts by
// element id, English and German; an instructor adds a language by adding a table here (same
// keys; a missing key keeps the English text). Texts are set with textContent only.
export const STRINGS = {
  en: {
    'bode-h': 'Frequency response',
    'tradeoff-h': 'Trade-off curves',
    pin: 'Pin this design',
    'pert-reset': 'Reset to nominal',
    'copy-link': 'Copy link',
    'copy-embed': 'Copy embed code',
    reveal: 'Reveal',
    hidden: 'hidden — what do you expect?',
    locked: 'locked by the instructor',
  },
  de: {
    'bode-h': 'Frequenzgang',
    'tradeoff-h': 'Zielkonflikt-Kurven',
    pin: 'Entwurf anheften',
    'pert-reset': 'Auf nominal zurücksetzen',
    'copy-link': 'Link kopieren',
    'copy-embed': 'Einbettungscode kopieren',
    reveal: 'Aufdecken',
    hidden: 'verborgen — was erwarten Sie?',
    locked: 'von der Lehrkraft gesperrt',
  },
};

/** The languages the table has. */
export const languages = () => Object.keys(STRINGS);

/** The text of `key` in `lang` (English when the language or the key is missing). */
export function t(lang, key) {
  const table = STRINGS[lang] || STRINGS.en;
  return key in table ? table[key] : STRINGS.en[key] !== undefined ? STRINGS.en[key] : key;
}

/** Sets the page's language: the elements whose id is a key of the table, and <html lang>. */
export function applyLanguage(lang) {
  if (!STRINGS[lang]) return;
  document.documentElement.lang = lang;
  for (const key of Object.keys(STRINGS.en)) {
    const node = document.getElementById(key);
    if (node) node.textContent = t(lang, key);
  }
}

//! The rules' small result caches, written once: a few results kept by an exact key (bit
//! patterns of the inputs), newest first. The searches they keep are deterministic, so a hit is
//! bit-identical to searching again. One per slow search: Algorithm III's designs, Praveen
//! Kumar's λ interval, Ms minimum and solved targets.

/// At most `cap` entries `(key, value)`, newest first.
pub(crate) struct Kept<K, V> {
    cap: usize,
    entries: Vec<(K, V)>,
}

impl<K: PartialEq, V: Clone> Kept<K, V> {
    /// An empty cache keeping at most `cap` entries.
    pub(crate) const fn new(cap: usize) -> Self {
        Kept {
            cap,
            entries: Vec::new(),
        }
    }

    /// The value kept for `key`, if any.
    pub(crate) fn get(&self, key: &K) -> Option<V> {
        self.entries
            .iter()
            .find(|e| e.0 == *key)
            .map(|e| e.1.clone())
    }

    /// Keeps `value` for `key` as the newest entry (replacing an entry of the same key),
    /// dropping the oldest beyond the capacity.
    pub(crate) fn put(&mut self, key: K, value: V) {
        self.entries.retain(|e| e.0 != key);
        self.entries.insert(0, (key, value));
        self.entries.truncate(self.cap);
    }

    /// The entries, newest first.
    pub(crate) fn iter(&self) -> impl Iterator<Item = &(K, V)> {
        self.entries.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::Kept;

    /// Exact-key lookup, replacement of an equal key, newest first, oldest dropped at capacity.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn keeps_the_newest_by_exact_key() {
        let mut k: Kept<u64, i32> = Kept::new(2);
        assert_eq!(k.get(&1), None);
        k.put(1, 10);
        k.put(2, 20);
        k.put(1, 11);
        assert_eq!(k.get(&1), Some(11));
        assert_eq!(k.iter().map(|e| e.0).collect::<Vec<_>>(), [1, 2]);
        k.put(3, 30);
        assert_eq!(k.get(&2), None, "the oldest is dropped");
        assert_eq!(k.iter().map(|e| e.1).collect::<Vec<_>>(), [30, 11]);
    }
}

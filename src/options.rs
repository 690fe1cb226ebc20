//! How to load and how to write: the options every stage reads, at the bottom of the crate
//! (they import nothing of it).

/// How to load: strictness and the limits of the input. Exceeding a limit is error
/// `limit-exceeded`, whose message names the limit.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LoadOptions {
    /// Largest input accepted, in bytes. Default 1 GiB.
    pub max_input_bytes: u64,
    /// Most elements in one file. Default 10 000 000.
    pub max_elements: u64,
    /// Longest node, in bytes: a tag (from its `<` to its `>`), a run of text, a CDATA
    /// section, a comment or a processing instruction (each from its first byte to its
    /// closing delimiter), and a value joined from several of them. Blank text between
    /// elements is not held to it. Default 1 MiB.
    pub max_text_bytes: u64,
    /// Deepest element nesting. Default 64.
    pub max_depth: u32,
    /// Most vertices in one chain shape. Default 100 000.
    pub max_chain_vertices: u32,
    /// Every warning becomes an error. Default false.
    pub strict: bool,
    /// Threads one load may use. 0 (the default) lets box2scene choose: a UTF-8 file of
    /// 1 MiB or more, in memory or read from its path (on Unix), is read on two threads,
    /// everything else on the calling thread. 1 never starts a thread; more than 2 is read as 2. The scene,
    /// its warnings and any error are the same however many threads read it.
    pub threads: u32,
}

impl Default for LoadOptions {
    fn default() -> LoadOptions {
        LoadOptions {
            max_input_bytes: 1 << 30,
            max_elements: 10_000_000,
            max_text_bytes: 1 << 20,
            max_depth: 64,
            max_chain_vertices: 100_000,
            strict: false,
            threads: 0,
        }
    }
}

/// How to write.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WriteOptions {
    /// Write every field of the file's version, even those equal to their defaults.
    /// Default false: omit them, as the original editor did.
    pub all_fields: bool,
    /// Kept so that the struct's layout stays as it was: a write runs on the calling
    /// thread, whatever this says, as one thread writes faster than a load reads.
    pub threads: u32,
    /// The dialect to write: a `b2s_dialect` value, or 0 (the default) for the one the scene
    /// remembers (that of the file it was loaded from; box2scene's own for a built scene).
    /// Farseer's dialects write every field, whatever `all_fields` says.
    pub dialect: u32,
}

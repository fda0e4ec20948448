// The translation unit that compiles a precompiled header; it has nothing of its own.

/** Types of bundle.mjs (plain JavaScript, so that it runs before anything is compiled). */

/** The compiled command line (git-ignored). */
export declare const CLI_BUNDLE: string;
/** Start of the bundle's first line, before its build record. */
export declare const CLI_BUILD_MARK: string;
/** True when the bundle exists and no source it was built from changed or vanished since its build started. */
export declare function cliBundleIsCurrent(bundle?: string, root?: string): boolean;
/** Bundles the command line into CLI_BUNDLE (atomically); throws when esbuild is missing or a source does not compile. */
export declare function buildCliBundle(): Promise<void>;

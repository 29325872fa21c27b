/** Moved to src/build/reference/oracles/ (the reference data set's generator uses it too); re-exported for the tests. */
export * from '../../src/build/reference/oracles/bruteForce';

import { describe, expect, it } from 'vitest';
import { CsvReader, type CsvRecord, csvField, csvText, isNumberText, parseCsv } from '../../src/cli/csv';
import { pick, random } from './helpers';

const fieldsOf = (records: readonly CsvRecord[]) => records.map((r) => r.fields);

describe('CSV reader (RFC 4180)', () => {
  it('reads plain records with LF, CRLF and CR line breaks, and the last record without one', () => {
    expect(fieldsOf(parseCsv('a,b\n1,2\r\n3,4\r5,6'))).toEqual([
      ['a', 'b'],
      ['1', '2'],
      ['3', '4'],
      ['5', '6'],
    ]);
    expect(parseCsv('a,b\n').map((r) => r.line)).toEqual([1]);
  });

  it('reads quoted fields: commas, doubled quotes and line breaks inside quotes are one record', () => {
    const records = parseCsv('R,note\n"3,5","say ""hi"""\n"1","two\nlines\r\nhere"\n4,x\n');
    expect(fieldsOf(records)).toEqual([
      ['R', 'note'],
      ['3,5', 'say "hi"'],
      ['1', 'two\nlines\r\nhere'],
      ['4', 'x'],
    ]);
    expect(records.map((r) => r.line)).toEqual([1, 2, 3, 6]);
    expect(records.every((r) => r.error === null)).toBe(true);
  });

  it('empty fields, an empty quoted field, spaces around a quoted field', () => {
    expect(fieldsOf(parseCsv(',,\n"",x\n  "a" , b\n'))).toEqual([
      ['', '', ''],
      ['', 'x'],
      ['a', ' b'],
    ]);
  });

  it('marks blank lines (empty or only spaces) as blank, but not a line with a quoted empty field', () => {
    const records = parseCsv('a\n\n   \n""\n,\n');
    expect(records.map((r) => r.blank)).toEqual([false, true, true, false, false]);
  });

  it('drops a byte-order mark at the start only', () => {
    expect(fieldsOf(parseCsv('\uFEFFR,h\n1,\uFEFF2'))).toEqual([
      ['R', 'h'],
      ['1', '\uFEFF2'],
    ]);
  });

  it('an unterminated quote is an error of that record, which runs to the end of the input', () => {
    const records = parseCsv('R,h\n1,"2\n3,4\n');
    expect(records).toHaveLength(2);
    expect(records[1]?.error).toMatch(/quoted field opened on line 2 is never closed/);
    expect(records[1]?.fields).toEqual(['1', '2\n3,4\n']);
  });

  it('a quote inside an unquoted field, or text after a closing quote, is an error of that record only', () => {
    const records = parseCsv('a"b,c\n"a"b,c\nok,1\n');
    expect(records[0]?.error).toMatch(/quote inside an unquoted field/);
    expect(records[1]?.error).toMatch(/text after the closing quote/);
    expect(records[2]).toEqual({ fields: ['ok', '1'], line: 3, error: null, blank: false });
  });

  it('a record longer than the limit is an error (its text is not kept) and the next record is read cleanly', () => {
    const long = 'x'.repeat(100);
    const records = parseCsv(`a,b\n${long},1\n"${long}\n${long}",2\n3,4\n`, 50);
    expect(records.map((r) => r.error)).toEqual([
      null,
      expect.stringMatching(/longer than 50 characters/),
      expect.stringMatching(/longer than 50 characters/),
      null,
    ]);
    expect(records[1]?.fields).toEqual([]);
    expect(records[3]).toEqual({ fields: ['3', '4'], line: 5, error: null, blank: false });
  });

  it('a record of exactly the limit is read, whatever ends it (LF, CRLF, CR, the end of input); one more is refused', () => {
    const exact = `${'1234567890,'.repeat(4)}123456789`; // 53 characters
    const quoted = `"${'x'.repeat(51)}"`; // 53 characters, the quotes counted
    const over = `${exact}0`;
    const text = `${exact}\n${quoted}\r\n${exact}\r${over}\n"a\nb",${'y'.repeat(47)}\n${exact}`;
    const records = parseCsv(text, 53);
    expect(records.map((r) => [r.line, r.error === null ? r.fields.length : r.error])).toEqual([
      [1, 5],
      [2, 1],
      [3, 5],
      [4, 'the record is longer than 53 characters: not read'],
      [5, 2], // a line break inside quotes is one of the record's characters: 5 + 1 + 47 = 53
      [7, 5],
    ]);
    expect(parseCsv(`${over}`, 53)[0]?.error).toMatch(/longer than 53/);
    expect(parseCsv(`"a\nb",${'y'.repeat(48)}\n`, 53)[0]?.error).toMatch(/longer than 53/);
  });

  it('holds at most the limit in memory for one huge record (10 MB, limit 1 MiB default)', () => {
    const reader = new CsvReader();
    const chunk = 'y'.repeat(1 << 16);
    let records: CsvRecord[] = reader.push('R,h\n');
    for (let i = 0; i < 160; i++) records = records.concat(reader.push(chunk));
    records = records.concat(reader.push('\n1,2\n'), reader.end());
    expect(records.map((r) => r.fields.length)).toEqual([2, 0, 2]);
    expect(records[1]?.error).toMatch(/longer than 1048576 characters/);
  });

  const seed = 20240607;
  it(`gives the same records whatever the chunks (seed ${seed}, 300 inputs split at random points)`, () => {
    const rand = random(seed);
    const pieces = ['a', '1.5', ',', '"', '""', '\n', '\r\n', '\r', ' ', 'x"y', '"q,"', '\uFEFF', 'é'];
    for (let k = 0; k < 300; k++) {
      let text = '';
      const n = 1 + Math.floor(rand() * 40);
      for (let i = 0; i < n; i++) text += pick(rand, pieces);
      const whole = parseCsv(text, 20);
      const reader = new CsvReader(20);
      const parts: CsvRecord[] = [];
      let at = 0;
      while (at < text.length) {
        const next = Math.min(text.length, at + Math.floor(rand() * 5));
        parts.push(...reader.push(text.slice(at, next)));
        at = next;
      }
      parts.push(...reader.end());
      expect(parts, JSON.stringify(text)).toEqual(whole);
    }
  });

  const seed2 = 77;
  it(`reads back what the writer quoted (seed ${seed2}, 500 random records)`, () => {
    const rand = random(seed2);
    const alphabet = ['a', '1', ',', '"', '\n', '\r\n', ' ', '=', '-', ''];
    for (let k = 0; k < 500; k++) {
      const fields: string[] = [];
      const n = 1 + Math.floor(rand() * 5);
      for (let i = 0; i < n; i++) {
        let f = '';
        const m = Math.floor(rand() * 6);
        for (let j = 0; j < m; j++) f += pick(rand, alphabet);
        // Leading or trailing spaces of an unquoted field are kept; the reader agrees.
        fields.push(f);
      }
      if (fields.length === 1 && fields[0]?.trim() === '') continue; // a blank line
      const records = parseCsv(`${fields.map(csvField).join(',')}\n`);
      expect(
        records.map((r) => r.fields),
        JSON.stringify(fields),
      ).toEqual([fields]);
      expect(records[0]?.error).toBeNull();
    }
  });
});

describe('CSV writer', () => {
  it('quotes a field with a comma, a quote or a line break, doubling quotes', () => {
    expect(csvField('plain')).toBe('plain');
    expect(csvField('a,b')).toBe('"a,b"');
    expect(csvField('say "hi"')).toBe('"say ""hi"""');
    expect(csvField('two\nlines')).toBe('"two\nlines"');
    expect(csvField('cr\r')).toBe('"cr\r"');
  });

  it('text that a spreadsheet would evaluate gets a leading quote; numbers do not', () => {
    expect(csvText('=1+2')).toBe("'=1+2");
    expect(csvText('+cmd')).toBe("'+cmd");
    expect(csvText('-x')).toBe("'-x");
    expect(csvText('@SUM(A1)')).toBe("'@SUM(A1)");
    expect(csvText('=HYPERLINK("x",1)')).toBe(`"'=HYPERLINK(""x"",1)"`);
    expect(csvText('-5')).toBe('-5');
    expect(csvText('+1.5e-3')).toBe('+1.5e-3');
    expect(csvText('3')).toBe('3');
    expect(csvText('zigzag')).toBe('zigzag');
  });

  it("numbers are the validation's plain decimals", () => {
    for (const t of ['1', '-1', '+.5', '1.', '1e-320', '2E+3']) expect(isNumberText(t)).toBe(true);
    for (const t of ['', '-', 'NaN', 'Infinity', '0x10', '1,5', '1e', '--1']) expect(isNumberText(t)).toBe(false);
  });
});

/* `cg trace ... --html OUT.html`: one self-contained page (no network: the
 * frames are inline PNG data URIs, the script and style inline) that shows
 * the trace's notes, its frame for the current step, that step's values and
 * the whole table with the current row marked.  Buttons, a slider and the
 * keys (left/right, Home/End, space to play) move through the steps. */
#include "trace_output.h"

#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void put_escaped(FILE *out, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '<': fputs("&lt;", out); break;
        case '>': fputs("&gt;", out); break;
        case '&': fputs("&amp;", out); break;
        case '"': fputs("&quot;", out); break;
        default: fputc(*s, out);
        }
    }
}

/* A JavaScript string literal (inside a <script>: "</" is split). */
static void put_js_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(out, "\\%c", c);
        else if (c == '<')
            fputs("\\u003c", out);
        else if (c < 0x20)
            fprintf(out, "\\u%04x", c);
        else
            fputc(c, out);
    }
    fputc('"', out);
}

static int put_base64_file(FILE *out, const char *path)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    FILE *in = fopen(path, "rb");
    if (!in)
        return -1;
    unsigned char b[3];
    size_t n;
    while ((n = fread(b, 1, 3, in)) > 0) {
        unsigned v = (unsigned)b[0] << 16 | (n > 1 ? (unsigned)b[1] << 8 : 0) | (n > 2 ? b[2] : 0);
        fputc(digits[v >> 18 & 63], out);
        fputc(digits[v >> 12 & 63], out);
        fputc(n > 1 ? digits[v >> 6 & 63] : '=', out);
        fputc(n > 2 ? digits[v & 63] : '=', out);
    }
    int bad = ferror(in);
    fclose(in);
    return bad ? -1 : 0;
}

/* The values of one step as "name = value" cells, for the page's table. */
static void put_step_values(FILE *out, const cg_step *s)
{
    fputc('[', out);
    for (int i = 0; i < s->field_count; i++) {
        char text[4096];
        trace_field_text(&s->fields[i], text, sizeof text);
        if (i)
            fputc(',', out);
        fputc('[', out);
        put_js_string(out, s->fields[i].name);
        fputc(',', out);
        put_js_string(out, text);
        fputc(']', out);
    }
    fputc(']', out);
}

static const char page_style[] =
    "body{font-family:sans-serif;margin:1em;color:#222}"
    "#frame{border:1px solid #aaa;image-rendering:pixelated;max-width:100%}"
    "pre{background:#f4f4f4;padding:.5em}"
    "table{border-collapse:collapse;font-family:monospace;font-size:90%}"
    "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}"
    "tr.now{background:#ffe0b0}#controls button{font-size:110%;margin-right:.3em}"
    "#where{font-weight:bold;margin-left:1em}";

/* Shows step i: its frame, its values, its row. */
static const char page_script[] =
    "var at=0,timer=null;\n"
    "function show(i){if(i<0)i=0;if(i>=steps.length)i=steps.length-1;at=i;\n"
    " document.getElementById('frame').src=frames[i];\n"
    " document.getElementById('slider').value=i;\n"
    " var s=steps[i];document.getElementById('where').textContent='step '+(i+1)+' of '+"
    "steps.length+(s.phase?' ('+s.phase+', step '+s.step+')':'');\n"
    " var t='';for(var k=0;k<s.values.length;k++)t+='<tr><th>'+esc(s.values[k][0])+'<\\/th><td>'+"
    "esc(s.values[k][1])+'<\\/td><\\/tr>';\n"
    " document.getElementById('values').innerHTML=t;\n"
    " var rows=document.querySelectorAll('#all tr[data-i]');\n"
    " for(var r=0;r<rows.length;r++)rows[r].className=(+rows[r].dataset.i===i)?'now':'';}\n"
    "function esc(t){return String(t).replace(/&/g,'&amp;').replace(/[<]/g,'&lt;');}\n"
    "function play(){if(timer){clearInterval(timer);timer=null;return;}\n"
    " timer=setInterval(function(){if(at+1>=steps.length){clearInterval(timer);timer=null;}"
    "else show(at+1);},400);}\n"
    "function table(){var h='',last=null;for(var i=0;i<steps.length;i++){var s=steps[i];\n"
    " var names=s.values.map(function(v){return v[0];}).join(' ');\n"
    " if(names!==last){h+='<tr><th>'+esc(s.phase||'')+'<\\/th>'+s.values.map(function(v){"
    "return '<th>'+esc(v[0])+'<\\/th>';}).join('')+'<\\/tr>';last=names;}\n"
    " h+='<tr data-i=\"'+i+'\" onclick=\"show('+i+')\"><td>'+s.step+'<\\/td>'+s.values.map("
    "function(v){return '<td>'+esc(v[1])+'<\\/td>';}).join('')+'<\\/tr>';}\n"
    " document.getElementById('all').innerHTML=h;}\n"
    "document.addEventListener('keydown',function(e){\n"
    " if(e.key==='ArrowRight'||e.key==='n')show(at+1);else if(e.key==='ArrowLeft'||e.key==='p')"
    "show(at-1);\n"
    " else if(e.key==='Home')show(0);else if(e.key==='End')show(steps.length-1);\n"
    " else if(e.key===' '){e.preventDefault();play();}});\n"
    "window.addEventListener('load',function(){var sl=document.getElementById('slider');\n"
    " sl.max=steps.length-1;sl.oninput=function(){show(+sl.value);};table();show(0);});\n";

static int write_page(FILE *out, const trace_run *run, const char *dir, int frame_count)
{
    fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>cg trace ",
          out);
    put_escaped(out, run->algorithm);
    fprintf(out, "</title>\n<style>%s</style>\n</head><body>\n<h1>", page_style);
    put_escaped(out, run->title);
    fputs("</h1>\n<p>cg trace ", out);
    put_escaped(out, run->algorithm);
    for (int i = 0; i < run->argc; i++) {
        fputc(' ', out);
        put_escaped(out, run->argv[i]);
    }
    fputs("</p>\n<pre>", out);
    for (int i = 0; i < run->note_count; i++) {
        put_escaped(out, run->notes[i]);
        fputc('\n', out);
    }
    put_escaped(out, run->summary);
    fputs("</pre>\n<div id=\"controls\"><button id=\"first\" onclick=\"show(0)\">&laquo; first"
          "</button><button id=\"previous\" onclick=\"show(at-1)\">&#x25C0; previous</button>"
          "<button id=\"next\" onclick=\"show(at+1)\">next &#x25B6;</button><button id=\"play\" "
          "onclick=\"play()\">play / pause</button><button id=\"last\" "
          "onclick=\"show(steps.length-1)\">last &raquo;</button>"
          "<input id=\"slider\" type=\"range\" min=\"0\" value=\"0\"><span id=\"where\"></span>"
          "</div>\n<p>Keys: &larr; &rarr; step, Home / End, space plays.  Orange: this step's "
          "pixels; blue: the pixels so far; red: the geometry this step looks at; green: the "
          "fixed input.</p>\n<div style=\"display:flex;gap:1em;align-items:flex-start\">"
          "<img id=\"frame\" alt=\"the picture at this step\"><table id=\"values\"></table>"
          "</div>\n<h2>All steps</h2>\n<table id=\"all\"></table>\n<script>\nvar frames=[\n",
          out);
    char path[4096];
    for (int i = 0; i < frame_count; i++) {
        snprintf(path, sizeof path, "%s/step_%04d.png", dir, i);
        fputs("\"data:image/png;base64,", out);
        if (put_base64_file(out, path) != 0)
            return cli_fail("trace: cannot read the frame %s back", path);
        fputs(i + 1 < frame_count ? "\",\n" : "\"\n", out);
    }
    fputs("];\nvar steps=[\n", out);
    size_t in_phase = 0;
    for (size_t i = 0; i < cg_step_log_count(run->log); i++) {
        const cg_step *s = cg_step_log_get(run->log, i),
                      *p = i ? cg_step_log_get(run->log, i - 1) : NULL;
        if (p
            && !((!p->phase && !s->phase) || (p->phase && s->phase && !strcmp(p->phase, s->phase))))
            in_phase = 0;
        fputs("{\"phase\":", out);
        put_js_string(out, s->phase ? s->phase : "");
        fprintf(out, ",\"step\":%zu,\"values\":", in_phase++);
        put_step_values(out, s);
        fputs(i + 1 < cg_step_log_count(run->log) ? "},\n" : "}\n", out);
    }
    fprintf(out, "];\n%s</script>\n</body></html>\n", page_script);
    return CLI_OK;
}

/* Removes the frames written to a temporary folder, and the folder. */
static void remove_frames(const char *dir, int count)
{
    char path[4096];
    for (int i = 0; i < count; i++) {
        snprintf(path, sizeof path, "%s/step_%04d.png", dir, i);
        remove(path);
    }
    rmdir(dir);
}

int trace_write_html(const trace_run *run, const char *frames_dir, int frame_count,
                     const char *path)
{
    char temporary_dir[] = "/tmp/cg-trace-XXXXXX";
    const char *dir = frames_dir;
    if (!dir) {
        if (!mkdtemp(temporary_dir))
            return cli_fail("trace: cannot make a temporary folder for the frames");
        dir = temporary_dir;
        if (trace_write_frames(run, dir, &frame_count) != CLI_OK) {
            remove_frames(dir, (int)cg_step_log_count(run->log));
            return CLI_FAILED;
        }
    }
    /* Written beside the target and renamed, so a failure leaves no half page. */
    size_t n = strlen(path) + 32;
    char *partial = malloc(n);
    int status = CLI_FAILED;
    if (partial) {
        snprintf(partial, n, "%s.partial-%ld", path, (long)getpid());
        FILE *out = fopen(partial, "wb");
        if (!out) {
            cli_fail("trace: cannot write %s", path);
        } else {
            status = write_page(out, run, dir, frame_count);
            if (fclose(out) != 0 && status == CLI_OK)
                status = cli_fail("trace: cannot write %s", path);
            if (status == CLI_OK && rename(partial, path) != 0)
                status = cli_fail("trace: cannot write %s", path);
            if (status != CLI_OK)
                remove(partial);
        }
        free(partial);
    }
    if (!frames_dir)
        remove_frames(dir, frame_count);
    return status;
}

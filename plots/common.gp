# plots/common.gp -- the terminal, size, fonts and line styles every hapstab figure shares.
#
# Every figure script is called as
#   gnuplot -e "plotdir='plots'; datadir='DATA'; outdir='OUT'; fmt='png'" plots/NAME.gp
# and starts with  name = 'NAME'; if (!exists("plotdir")) plotdir = 'plots'; load plotdir.'/common.gp'
# fmt: png (screens, 1600x1000 px), pdf (papers, 6x3.75 in), svg, tex (cairolatex + pdf,
# for \input{NAME.tex} in LaTeX: text is typeset by LaTeX in the document's font).
if (!exists("fmt")) fmt = 'png'
if (!exists("datadir")) datadir = 'out/data'
if (!exists("outdir")) outdir = 'out/figures'
# wide = 1 (set before loading this file): a figure of several panels whose PDF / LaTeX version
# needs 1.5x the canvas at the same font size (a two-column figure*)
# tall = 1: two rows of panels, 1.6x the height in every format; tall = 2: three rows, 2.4x
if (!exists("wide")) wide = 0
if (!exists("tall")) tall = 0
pdf_w = (wide ? 9.0 : 6.0); tex_w = (wide ? 7.5 : 5.0); hf = (tall == 2 ? 2.4 : tall ? 1.6 : 1.0)
# canvas: png 1600 x 1000 px, svg 1200 x 750, pdf pdf_w x 0.625 pdf_w in, tex tex_w x 0.62 tex_w in
png_w = 1600.0; png_h = 1000.0*hf; svg_w = 1200.0; svg_h = 750.0*hf; pdf_h = pdf_w*0.625*hf; tex_h = tex_w*0.62*hf
# size_w_cm, size_h_cm (set by the caller, e.g. sweep plot --size): the paper size of pdf and tex,
# and the same layout at the same font sizes for png (1600 px per 6 in) and svg (1200 px per 6 in)
if (exists("size_w_cm")) { pdf_w = size_w_cm/2.54; pdf_h = size_h_cm/2.54; tex_w = pdf_w; tex_h = pdf_h; \
  png_w = pdf_w*1600/6.0; png_h = pdf_h*1600/6.0; svg_w = pdf_w*1200/6.0; svg_h = pdf_h*1200/6.0 }
if (fmt eq 'png') { set terminal pngcairo size png_w,png_h enhanced font 'DejaVu Sans,22' linewidth 2; set output outdir.'/'.name.'.png' }
if (fmt eq 'pdf') { set terminal pdfcairo size pdf_w*1in,pdf_h*1in enhanced font 'DejaVu Sans,10' linewidth 1.5; set output outdir.'/'.name.'.pdf' }
if (fmt eq 'svg') { set terminal svg size svg_w,svg_h enhanced font 'DejaVu Sans,16' linewidth 2 background rgb 'white'; set output outdir.'/'.name.'.svg' }
if (fmt eq 'tex') { set terminal cairolatex pdf size tex_w*1in,tex_h*1in linewidth 1.5; set output outdir.'/'.name.'.tex' }
tex = (fmt eq 'tex')
# font sizes relative to the terminal's own (22 pt png, 10 pt pdf/tex, 16 pt svg), for keys,
# labels and notes: `font small`, `font note` (an absolute ',16' would be tiny in one format
# and huge in another)
basefont = (fmt eq 'png' ? 22 : fmt eq 'svg' ? 16 : 10)
small = sprintf(',%g', 0.8 * basefont)
note = sprintf(',%g', 0.65 * basefont)
# one font size (em) as a fraction of the canvas width / height, for margins that keep their room
# for text in every format: `set lmargin at screen 6*emx`
emx = basefont / (fmt eq 'png' ? png_w : fmt eq 'svg' ? svg_w : fmt eq 'pdf' ? 72 * pdf_w : 72 * tex_w)
emy = basefont / (fmt eq 'png' ? png_h : fmt eq 'svg' ? svg_h : fmt eq 'pdf' ? 72 * pdf_h : 72 * tex_h)
set border lw 1
set grid lc rgb '#d0d0d0' lw 0.5
set key box opaque samplen 2 spacing 1.1
set style line 1 lc rgb '#0072B2' lw 2 pt 7 ps 1.0
set style line 2 lc rgb '#D55E00' lw 2 pt 5 ps 1.0
set style line 3 lc rgb '#009E73' lw 2 pt 9 ps 1.0
set style line 4 lc rgb '#CC79A7' lw 2 pt 11 ps 1.0
set style line 5 lc rgb '#E69F00' lw 2 pt 13 ps 1.0
set style line 6 lc rgb '#56B4E9' lw 2 pt 3 ps 1.0
# the same colours as a list (word(pal, i) is line style i's), and as the default line types
pal = '#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9'
do for [i=1:6] { set linetype i lc rgb word(pal, i) lw 2 }
set linetype cycle 6
set style line 7 lc rgb '#000000' lw 1.5 dt 2
set style line 8 lc rgb '#808080' lw 1 dt 3

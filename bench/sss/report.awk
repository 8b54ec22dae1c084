# report.awk - the markdown tables of bench/sss/README.md from results.csv and bias.csv
# (awk -F, -f report.awk results.csv bias.csv). Equal-time errors come from a least-squares line
# through log(MSE) against log(spp) of each method's series and its time per sample (see fit),
# read at the longest time every method of the scene reached.
BEGIN { FIT_MIN_SPP = 4; nmeth = split("circle fullcircle talk disk volume auto", order, " ") }

FNR == 1 { file++; next }

# results.csv: scene,material,method,spp,seconds,wall_seconds,rmse,relmse,efficiency,nohit_rate,dropped,reference
file == 1 {
	s = $1; m = $3
	if (!(s in seen_scene)) { seen_scene[s] = 1; scenes[++nscenes] = s; mat[s] = $2 }
	has[s, m] = 1
	key = s SUBSEP m SUBSEP $4
	if (!(key in row_seen)) { row_seen[key] = 1; rows[s, m, ++nrows[s, m]] = $4 }
	sec[key] = $5; nohit[key] = $10; dropped[key] = $11
	if ($12 == "self") { rmse[key] = $7; relmse[key] = $8; eff[key] = $9 }
	else { vrmse[key] = $7; vrelmse[key] = $8 }
	next
}

# bias.csv: scene,material,method,against,rmse,relmse,noise_rmse,bias_rmse,mean_ratio
file == 2 {
	nb++; b_s[nb] = $1; b_mat[nb] = $2; b_m[nb] = $3; b_a[nb] = $4; b_r[nb] = $5; b_q[nb] = $6
	b_n[nb] = $7; b_b[nb] = $8; b_mr[nb] = $9
}

function num(x) { return x != "NA" && x != "" && x + 0 > 0 }

# fit(s, m): over the series of (s, m) (counts >= FIT_MIN_SPP, or every count when fewer than two
# reach it), least squares log(MSE) = fa + fb log(spp), and the render time per sample per pixel
# tps = sum of seconds / sum of spp (dominated by the longest, best-timed renders); tmax the longest
# time. Fitting against spp rather than seconds keeps each render's timing noise out of the slope.
function fit(s, m,    k, n, sx, sy, sxx, sxy, st, sn, x, y, sp, key, minspp) {
	minspp = FIT_MIN_SPP
	n = 0
	for (k = 1; k <= nrows[s, m]; k++) {
		sp = rows[s, m, k]; key = s SUBSEP m SUBSEP sp
		if (sp + 0 >= minspp && num(sec[key]) && num(rmse[key])) n++
	}
	if (n < 2) minspp = 1
	n = sx = sy = sxx = sxy = st = sn = 0; tmax = 0
	for (k = 1; k <= nrows[s, m]; k++) {
		sp = rows[s, m, k]; key = s SUBSEP m SUBSEP sp
		if (sp + 0 < minspp || !num(sec[key]) || !num(rmse[key])) continue
		x = log(sp); y = 2 * log(rmse[key])
		n++; sx += x; sy += y; sxx += x * x; sxy += x * y; st += sec[key]; sn += sp
		if (sec[key] + 0 > tmax) tmax = sec[key] + 0
	}
	if (n < 2 || n * sxx - sx * sx <= 0) return 0
	fb = (n * sxy - sx * sy) / (n * sxx - sx * sx)
	fa = (sy - fb * sx) / n
	tps = st / sn
	return 1
}

# rmse_at(s, m, t): the fitted RMSE of (s, m) after t seconds ("" when it cannot be fitted).
function rmse_at(s, m, t) { return fit(s, m) ? exp((fa + fb * log(t / tps)) / 2) : "" }

# geo_eff(s, m): geometric mean of 1/(MSE t) over the series (counts >= FIT_MIN_SPP).
function geo_eff(s, m,    k, n, l, key) {
	n = l = 0
	for (k = 1; k <= nrows[s, m]; k++) {
		key = s SUBSEP m SUBSEP rows[s, m, k]
		if (rows[s, m, k] + 0 >= FIT_MIN_SPP && num(eff[key])) { n++; l += log(eff[key]) }
	}
	return n ? exp(l / n) : ""
}

# t_common(s): the longest time every method of s reached (the smallest of their longest times).
function t_common(s,    i, m, t) {
	t = ""
	for (i = 1; i <= nmeth; i++) {
		m = order[i]
		if (!has[s, m] || !fit(s, m)) continue
		if (t == "" || tmax < t) t = tmax
	}
	return t
}

function top_key(s, m) { return s SUBSEP m SUBSEP rows[s, m, nrows[s, m]] }
function f3(x) { return (x == "" || x == "NA") ? "–" : sprintf("%.3g", x) }
function ratio(a, b) { return (a == "" || b == "" || b == 0) ? "–" : sprintf("%.2f", a / b) }

END {
	# Headline: circle against disk at equal time.
	print "### Headline: circle vs disk at equal time (noise against each method's own reference)"
	print ""
	print "| scene | material | equal time (s) | circle RMSE | disk RMSE | circle / disk RMSE | disk / circle efficiency |"
	print "|---|---|---|---|---|---|---|"
	for (i = 1; i <= nscenes; i++) {
		s = scenes[i]
		if (!has[s, "circle"] || !has[s, "disk"]) {
			printf "| %s | %s | – | – | – | (disk not run) | – |\n", s, mat[s]
			continue
		}
		fit(s, "circle"); tc = tmax; fit(s, "disk"); t = tmax < tc ? tmax : tc
		c = rmse_at(s, "circle", t); d = rmse_at(s, "disk", t)
		ec = geo_eff(s, "circle"); ed = geo_eff(s, "disk")
		printf "| %s | %s | %.3g | %s | %s | **%s** | %s |\n", s, mat[s], t, f3(c), f3(d), ratio(c, d), ratio(ed, ec)
	}
	print ""
	print "Below 1: circle's image is less noisy than disk's for the same render time."
	print ""

	# Every method at equal time, relative to circle.
	print "### Every method at equal time: RMSE relative to circle's (own reference), and no-hit rates"
	print ""
	hdr = "| scene | material | time (s) | circle RMSE"
	sep = "|---|---|---|---"
	for (j = 2; j <= nmeth; j++) { hdr = hdr " | " order[j] " / circle"; sep = sep "|---" }
	for (j = 1; j <= nmeth; j++) { hdr = hdr " | no-hit " order[j]; sep = sep "|---" }
	print hdr " |"; print sep "|"
	for (i = 1; i <= nscenes; i++) {
		s = scenes[i]; t = t_common(s)
		if (t == "" || !has[s, "circle"]) continue
		c = rmse_at(s, "circle", t)
		line = sprintf("| %s | %s | %.3g | %s", s, mat[s], t, f3(c))
		for (j = 2; j <= nmeth; j++) {
			m = order[j]
			line = line " | " (has[s, m] ? ratio(rmse_at(s, m, t), c) : "–")
		}
		for (j = 1; j <= nmeth; j++) {
			m = order[j]
			line = line " | " (has[s, m] && num(nohit[top_key(s, m)]) ? sprintf("%.2g", nohit[top_key(s, m)]) : (has[s, m] ? nohit[top_key(s, m)] : "–"))
		}
		print line " |"
	}
	print ""

	# Model bias.
	if (nb) {
		print "### Bias: each method's reference against volume's (model) and circle's (estimator)"
		print ""
		print "| scene | material | method | against | RMSE | relMSE | noise RMSE of the two references | bias RMSE (beyond noise) | mean brightness |"
		print "|---|---|---|---|---|---|---|---|---|"
		for (k = 1; k <= nb; k++)
			printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", b_s[k], b_mat[k], b_m[k], b_a[k], f3(b_r[k]),
				f3(b_q[k]), f3(b_n[k]), b_b[k] == 0 ? "0" : f3(b_b[k]),
				num(b_mr[k]) ? sprintf("%+.1f %%", 100 * (b_mr[k] - 1)) : "–"
		print ""
		print "bias RMSE = sqrt(RMSE^2 - noise^2): the part of the difference the references' noise does not"
		print "explain (0: none resolved); it is only as good as the noise estimate (see the caveats). Mean"
		print "brightness: the mean of the method's image over the other's, minus 1 (negative: darker)."
		print ""
	}

	# Every render.
	print "<details><summary>Every render of the series (results.csv)</summary>"
	print ""
	print "| scene | method | spp | seconds | RMSE | relMSE | efficiency | RMSE vs volume | relMSE vs volume | no-hit |"
	print "|---|---|---|---|---|---|---|---|---|---|"
	for (i = 1; i <= nscenes; i++) {
		s = scenes[i]
		for (j = 1; j <= nmeth; j++) {
			m = order[j]
			if (!has[s, m]) continue
			for (k = 1; k <= nrows[s, m]; k++) {
				key = s SUBSEP m SUBSEP rows[s, m, k]
				printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", s, m, rows[s, m, k], sec[key],
					f3(rmse[key]), f3(relmse[key]), f3(eff[key]),
					(key in vrmse) ? f3(vrmse[key]) : "–", (key in vrelmse) ? f3(vrelmse[key]) : "–", nohit[key]
			}
		}
	}
	print ""
	print "</details>"
}
